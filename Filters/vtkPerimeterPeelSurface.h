/**
 * @class   vtkPerimeterPeelSurface
 * @brief   Surface of a point cloud by peeling its Delaunay tetrahedralization from the convex
 *          hull inwards (Rodriguez, Espadero, Lopez, Pastor, DGCI 2000, section 3)
 *
 * The input is any vtkPointSet; only its points matter. The points are tetrahedralized exactly
 * (the kernel of vtkIncrementalDelaunay3D; NaN/Inf points are skipped, duplicates merged: exact
 * copies, and the points of a pile of near-coincident points, see below)
 * and the solid made of the tetrahedra is peeled (paper section 3, steps 2-7):
 *
 * - the exterior facets are the facets of the solid that only one of its tetrahedra owns; at the
 *   start, the convex hull (step 3);
 * - threshold = mean measure of the exterior facets x ThresholdFactor (step 4), or Threshold
 *   when it is positive (a fixed threshold, the paper's user threshold: a single pass);
 * - every exterior facet over the threshold removes the tetrahedron that owns it, whose other
 *   facets become exterior (steps 5-6); the largest facets go first (a priority queue), so the
 *   result does not depend on the input order and each tetrahedron is removed at most once;
 * - the mean is recomputed; while it moved by more than ConvergenceTolerance (relative), the
 *   threshold is updated and peeling continues (step 7), at most MaximumIterations times.
 *
 * The facet measure is FacetMeasure: the perimeter (the paper's choice, default), the area or
 * the circumradius (the alternatives the paper weighs; it found the perimeter better, and so do
 * the tests here: on random samples the area and circumradius of the surface triangles spread
 * much more than their perimeter, so a torus's hole may stay closed or small handles open).
 *
 * Beyond the paper:
 * - Relative measures (LocalSpacingNeighbors > 0, default 6): each facet's measure is divided by
 *   the local spacing at its three vertices, so that one threshold fits dense and sparse regions
 *   (the paper's caveat below). A point's local spacing is the mean length of its
 *   LocalSpacingNeighbors shortest Delaunay edges (its nearest neighbours: the nearest-neighbour
 *   graph is a subgraph of the Delaunay graph, so no neighbour search is needed; when the
 *   longest is over 8 times their median, at most 1.5 times the median), averaged twice over the
 *   same neighbours; on a uniform sample it is nearly constant (the paper's rule up to a factor).
 *   FinalThreshold is then in units of the local spacing. On the vertices of CGAL's demo meshes
 *   (graded) it raised the coverage from 0.76-0.97 to 0.96-0.998 and removed the caves dug under
 *   sparse regions (see the README). The bound on the mean is for flat regions: there a point's
 *   Delaunay neighbours in the plane are its 2D Delaunay neighbours (6 on average, often 4 or 5),
 *   and its other shortest edges cross the inside of the object (on 10^5 random points of a
 *   cube's faces the mean was 2.7 times the true spacing, and the peel dug caves 43 spacings deep
 *   through the faces; 1.6-1.9 with the bound, 9 seeds; on the 9 CGAL mesh vertex sets of the
 *   benchmark no coverage drops).
 * - No point is lost by peeling: a tetrahedron is kept when removing it would leave one of its
 *   vertices in no tetrahedron (the paper's "loss of vertices"), but for the points held only by a
 *   strut (rule 8). Points that the surface does not use (inside the solid, duplicates, or left
 *   by a strut) have point data `Used` = 0 and are counted.
 * - ManifoldOutput (default on): the boundary of the solid is a closed 2-manifold at every step,
 *   so no repair is needed afterwards (a sculpting peel).
 *   1. One tetrahedron is removed only when the sculpting rules allow it (Boissonnat 1984,
 *      "Geometric structures for three-dimensional shape representation", ACM TOG 3(4)): with
 *      one exterior facet, the opposite vertex is not on the boundary yet; with two, the edge
 *      joining their opposite vertices is not on it; with three or four, never (a point would be
 *      left in no tetrahedron). A refused tetrahedron is tried again when a neighbour goes.
 *   2. Widest way in: a tetrahedron is not removed when it would show the outside a facet more
 *      than 1.5 times larger than the bottleneck of its widest way in from the hull, if that
 *      bottleneck is within GroupFactor x threshold. A way in is a chain of removed tetrahedra
 *      entered through exterior facets; its bottleneck is the smallest facet it passes through.
 *      The widest way in to a tetrahedron is the largest, over its exterior facets, of min(the
 *      facet, the bottleneck recorded for the tetrahedron behind it when that one went); the
 *      hull's bound is infinite, and the tetrahedra of a group removal (rule 3) all record the
 *      widest way in to the group's first tetrahedron. On a random sample some true surface
 *      triangles are over the mean, and removing the tetrahedron under one of them would dig a
 *      cave into the object (its hidden facets span the inside), while neighbouring surface
 *      triangles differ by less, and a peel coming from the hull meets shrinking facets.
 *      Until 2026-11-24 only the tetrahedron's own exterior facet counted, and the peel dug
 *      under noisy samples in steps each under 1.5 times: with Gaussian noise of 0.1 spacing the
 *      hull facets over the noisy layer measure 9-10 local spacings (over the cave limit, rule
 *      4), and on 20,000 random points of a sphere (threshold 7.9) the peel went from a facet of
 *      9.6 through 10.3, 11.0, 12.8, 15.7, 20.3, 28.4 and 30.2 to 38.9 (over GroupFactor x
 *      threshold: no rule) and emptied the solid: a double layer, closed, manifold, genus 0,
 *      enclosing 0.7 % of the volume (torus 4 %, a cube's faces 10-12 % on 2 of 3 seeds); now
 *      99.7 % (torus 99.3 %, cube 99.4 %; Benchmarks/results/peel.md). Tried and not kept: the
 *      smallest facet on any way in (instead of the widest) left lids across the goblet's cup;
 *      groups starting ways of no bound let a group started at a cave's wall (a refused facet
 *      over GroupFactor x threshold) open the inside of a random ellipsoid (30 % of its volume
 *      lost). With the AREA measure only the tetrahedron's own exterior facet counts (slivers'
 *      triangles have nearly no area, so a way's smallest area says nothing of the surface).
 *   3. Removals of one tetrahedron that keep the boundary a manifold never change the topology
 *      of the solid: the hole of a torus opens only when a whole layer of tetrahedra goes at
 *      once. When the peeling stalls, a group removal starts at each refused tetrahedron whose
 *      exterior facet exceeds GroupFactor x threshold (largest first). The group grows, largest
 *      facet first, across facets over the threshold into the tetrahedra behind them (the
 *      paper's rule applied to a group), never into a tetrahedron that shows the outside a facet
 *      under the threshold (a surface facet already), and stops at the first cell after which the
 *      boundary is a manifold around every vertex of the group again: in the link of the vertex,
 *      the inside cells form one component, the outside cells one, and each edge has at most two
 *      boundary triangles. (The links are checked after every cell, lazily: a vertex found
 *      non-manifold whose cells have not changed since is not checked again. A group that went on
 *      past a manifold state, as when the links were checked only when the group doubled, pinched
 *      the boundary again and burrowed along a torus's tube to the size bound: random tori of
 *      10^5 points stayed genus 0.)
 *      A cell whose removal would leave a point in no tetrahedron is not entered. The group is
 *      given up (and its tetrahedra are not tried again at this threshold: O(n) per threshold)
 *      when no cell is left to enter or it reaches max(8192, cells / 256) tetrahedra (the
 *      successful groups measured had at most a few hundred; a failing one burrows into the
 *      solid through its large inner facets, so this bound sets the cost of the failures).
 *      The Euler characteristic of the boundary tells what a group does: it drops by 2 when a
 *      handle opens, stays when the topology stays (e.g. the flat layers of nearly cocircular
 *      points over a torus's hole go), and grows when a bridge goes (a handle closes, e.g. a
 *      strip left across a hole) or a part splits off; the last only under rule 9 (a search
 *      through the remaining tetrahedra checks whether the cells around the group stay connected).
 *      HandleFactor (default 1: off) can ask for stronger evidence before a handle opens: a
 *      group of at most 8 tetrahedra then opens one only when its start facet exceeds
 *      HandleFactor x GroupFactor x threshold (squared for AREA). It was 2 until 2026-11-23,
 *      against tunnels of 3-5 tetrahedra between two dents of dense random spheres (start facets
 *      4.0-4.8 x threshold), which the cave limit (rule 4) now prevents: 10^5-point random
 *      spheres, seeds 1-16, are genus 0 either way. At 2 it kept webs: layers of flat tetrahedra
 *      one or two spacings thick, outside the object on both sides, spanning concave regions
 *      (their facets 11-20 local spacings, 3.5-6 x threshold); each short group punching one
 *      opened a handle without a start facet over 2 x GroupFactor x threshold, so the web stayed
 *      (CGAL's diplodocus vertices: Hausdorff distance 5.3 mean spacings; refined_elephant: genus
 *      2 of 3). At 1 the punched webs are cleared by the groups that follow (which close the
 *      handles again as bridges): diplodocus 3.2 (3.6 with the local spacing bound, above),
 *      refined_elephant genus 3.
 *   4. Cave limit (CaveLimit, relative measures only): a tetrahedron whose exterior facets are all
 *      at most as large as an equilateral triangle of perimeter CaveLimit local spacings (default
 *      9) is kept when its removal would show the outside a larger facet. Rule 2 stops a cave only
 *      where one step shows a facet 1.5 times larger; the caves on CGAL's mesh vertices were dug
 *      in smaller steps from a surface triangle (5, 7, 10, 15, ... spacings) down to walls of
 *      11-32 spacings. A uniform sample's surface triangles have perimeters of about 3 local
 *      spacings, and a peel coming from the hull meets shrinking facets, so the limit leaves both
 *      alone. Measured (2026-11-23): Hausdorff distance on the 9 mesh vertex sets of the benchmark
 *      15.0 24.9 12.2 6.4 23.7 12.2 3.1 10.3 14.3 -> 3.6 3.2 4.0 2.7 4.9 2.6 3.1 10.3 5.3 mean
 *      spacings, same genus, coverage within 0.006 (armadillo 0.965 -> 0.999); 20,000 random
 *      points of a cube's surface: deepest triangle centroid 19 -> 1.7 spacings (at 10^5 points a
 *      cave of 43 spacings stayed: a bias of the local spacing on flat regions, bounded since).
 *   5. Group start limit (GroupStartLimit, relative measures only): when the peel has converged
 *      with GroupFactor x threshold over an equilateral triangle of perimeter GroupStartLimit
 *      local spacings (default 12: GroupFactor's default times the perimeter of a uniform
 *      sample's surface triangle, about 3), it goes on with group removals starting at facets
 *      over that limit too, and iterates until the mean settles again. The mean counts the
 *      facets of what the peel could not remove: sheets of flat tetrahedra across the holes of
 *      CGAL's knot2 (facets 10-30 local spacings) held its threshold at 9 and the group start at
 *      36, so no group started and 46 % of the points stayed under the sheets. Short groups
 *      from the limit open no handle unless their start facet is over HandleFactor x
 *      GroupFactor x threshold (rule 3). Measured (2026-11-23): knot2 Hausdorff 10.2 -> 3.6 mean
 *      spacings, coverage 0.54 -> 1.0, genus 0 -> 2 (its mesh's); knot1 genus 0 -> 1 (its
 *      mesh's); refined_elephant 4.9 -> 1.9 (a web just under the group start); the 6 other
 *      mesh vertex sets unchanged; no genus change on random spheres and tori.
 *   6. Unfolding (after the peel): on samples of smooth surfaces the peel leaves thin flaps of
 *      flat tetrahedra (nearly cospherical points) that were kept while a neighbour went, so that
 *      one of their triangles faces into the solid. A fold is a boundary edge whose two triangles'
 *      outward normals are more than 90 degrees apart. At each fold, cells next to it move to the
 *      other state (removed or put back): one cell on either side of its two triangles, under the
 *      sculpting rules both ways (rule 1; a cell is put back only when it shares two facets with
 *      the solid and the edge joining their opposite vertices is not in it), or all the inside
 *      or all the outside cells around its edge (2 to 8; the group checks of rule 3: manifold
 *      links, the same Euler characteristic, nothing split off or enclosed), when every vertex of
 *      the cells stays on the boundary (no point lost) and the edges of the moved cells then have
 *      fewer folds, or as many and less bending (the sum of 1 - cosine of the angle between the
 *      normals). Every move lowers the whole surface's folds or bending, so the pass ends (it is
 *      also bounded by the number of cells). The topology, the points used and the manifold
 *      stay. Measured (2026-11-24; 20,000 random points, triangles whose normal points into the
 *      true solid): sphere 13 % -> 2.5 %, with Gaussian noise of 0.1 spacing 17 % -> 10 %, noisy
 *      torus 16 % -> 9 % (exact torus: 3 -> 0 triangles); the rest needs several cells at once
 *      in ways these moves do not reach (on noisy samples a fold-free surface over the Delaunay
 *      facets through every point may not exist). Cost: 10^5 random sphere points, the peel's
 *      processor time 0.33 -> 0.72 s (70,000 folds) when introduced; each trial is now evaluated
 *      without moving anything (a single cell from its four facets and at most one short walk
 *      per edge, a fan by one walk around each edge of its cells for both states): 10^6 random
 *      sphere points, the peel 5.15 -> 3.4 s; field data NumberOfUnfoldingMoves.
 *   7. Groups that keep the topology (during the peel, once it has converged): group removals
 *      also start at refused tetrahedra whose exterior facet is over twice the threshold (squared
 *      for AREA; a surface triangle of a uniform sample is about the mean), grow as in rule 3 but
 *      go on past a manifold state that has opened a handle, and are accepted only when the
 *      boundary's Euler characteristic is unchanged, or grew by closing a handle with the solid
 *      still in one piece (a bridge; never a handle opened, nothing split off), and they show the
 *      outside no facet larger than their start facet (a peel from outside meets shrinking
 *      facets; a cave would show larger ones). They remove the bumps and
 *      webs of large, nearly regular tetrahedra left over concave regions, whose vertices are all
 *      on the boundary (so no single tetrahedron may go) and whose facets (5-9 local spacings)
 *      are under every group start of rules 3 and 5. Measured (2026-11-24, Hausdorff distance in
 *      mean spacings on CGAL's mesh vertices): bunny00 2.55 -> 1.46, elephant 2.46 -> 1.67,
 *      refined_elephant 0.86 -> 0.66, knot1 2.91 -> 0.23, the 5 others unchanged (camel 4.03: its
 *      web between the legs opens a handle when punched, so only a group that may open one clears
 *      it), same genus and coverage within 0.0004 (up); the same with 1.5 or 2.5 times the
 *      threshold. Without the facet condition, 2 times made armadillo's worse (2.90 -> 3.15).
 *      Bridges (accepted since 2026-11-24): where the peel leaves a web across a slot between
 *      two nearby parts, groups of rule 3 may punch it in several places, and the strips left
 *      between the holes are spurious handles. Measured on two parallel tubes 10-14 mean spacings
 *      apart, joined at one end (genus 0) or both (genus 1; 20,000 random points, 3 seeds per
 *      gap, Benchmarks/run_peel_web_benchmark.py): handles in excess 39 -> 19 in 30 clouds, none
 *      added; CGAL's man vertices genus 1 -> 0 (its mesh's); the 9 benchmark sets unchanged.
 *   8. Struts: a group of rules 3, 5 or 7 may leave a point in no tetrahedron (it is then reported
 *      unused, counted in NumberOfStrutPoints) when the point's last tetrahedron holds it by
 *      facets that all measure over the group start (GroupFactor x threshold, or the group start
 *      limit of rule 5: clearly not surface triangles), at most 2 points per group, and never in
 *      a group that opens a handle. On random samples the peel may remove every tetrahedron of a
 *      surface point but one (the no-point-lost rule keeps the last) that spans a gap to a facing
 *      part: a strut or spike several spacings long held up by that one point, which no group
 *      could remove before. The trade-off: one point of the sample off the surface (within about
 *      a spacing of it, as the surface goes through its neighbours) against triangles as far from
 *      the surface as half the gap. The "whichever keeps more points" is about pinches;
 *      a strut held by one point is not one. Measured (2026-11-24, Benchmarks/results/peel.md):
 *      CGAL's elephant, random 10^5-point sample seed 2: Hausdorff distance 18.52 -> 11.33 mean
 *      spacings, genus 4 -> 3 (a strut of 4 tetrahedra across 34 spacings was a bridge), 2 points
 *      more unused; on 20 such samples of camel, elephant, armadillo and bunny00 the other
 *      distances are unchanged (1 point more unused on camel seeds 1-4; elephant seed 5 genus 2
 *      -> 3); the 9 mesh vertex sets and the web benchmark unchanged. Webs (membranes of many
 *      tetrahedra across such gaps) are not struts: their groups still burrow into the solid.
 *   9. Separate objects: a group of rules 3 or 5 (not 7) that splits the solid in two (the Euler
 *      characteristic of the boundary +2, the cells around the group no longer connected) is
 *      accepted when every facet it takes off the boundary measures over the group start
 *      (GroupFactor x threshold, or the group start limit of rule 5): a neck made only of facets
 *      that are clearly not surface triangles, as the peel leaves between two objects. Each part
 *      is a closed 2-manifold (the links are checked as for any group) and a point held only by
 *      the neck is reported unused (rule 8). A sampled thin part of one object (a dumbbell's
 *      handle, legs, a knot's tube) keeps surface triangles of the sampling's size, which no group
 *      enters (rule 3) nor takes (this rule), so it stays. Before 2026-11-24 every split was
 *      refused: two random unit spheres of 20,000 points each, centres 5 apart, came out as one
 *      genus-0 surface joined by a neck of 6 triangles up to 41 spacings from the spheres (the
 *      group removing its 3 tetrahedra split the solid), as did three or nine spheres; now one
 *      closed genus-0 component per sphere, every triangle within 0.2 spacing of its sphere.
 *      Limits: objects closer than about 4 spacings stay joined by a web whose facets are under
 *      the group start (as handles narrower than that stay closed); a thread of radius about one
 *      spacing, sampled at random, may be cut where its sample has a gap (1 of 2 seeds). Nested
 *      objects: the inner one is inside the solid, its points unused (the output bounds a solid).
 * - Duplicate points are tetrahedralized once (the others have `Used` = 0 and are counted in
 *   NumberOfDuplicatePoints, with a warning): exact copies (the copy of smallest id, merged
 *   before the tetrahedralization on the outlier rule's search, so that copies change neither
 *   the kernel's insertion order nor its cell numbering: the cloud with copies gives the same
 *   triangles as without them; 1 copy of 285 of 2,000 sphere points changed 494 of 3,996
 *   triangles before 2026-11-24), and the points of a pile of near-coincident points (a scanner's repeated
 *   returns at one spot, jittered copies), as in vtkCDTAdvancingFront: a group whose extent is
 *   under 1/10,000 of its distance to the rest of the cloud, found on the table of the 8 nearest
 *   neighbours the outlier rule below searches (pcs::FindPiles, the definition
 *   vtkCDTAdvancingFront's duplicates and the outlier rule share; with OutlierFactor 0 the table
 *   is searched for the piles alone); the Delaunay kernel gets the pile's point of smallest id
 *   only. The tolerance is relative to the sampling around the group, no absolute or global
 *   distance. A pile tetrahedralized point by point made a blob of needle triangles on the
 *   surface: 1,000 sphere points and 4 piles of 600 gave 6,758 triangles, 4,762 of them with an
 *   edge under 1e-5 of the radius (now 1,996, 2V - 4; Benchmarks/results/robustness.md, "Piles
 *   are duplicates in LOG, greedy and the peel").
 * - Far outliers (OutlierFactor, default 8): isolated points, clumps and sparse clutter far from
 *   the surface would make the peel stop at their hull (the paper assumes none). They are left
 *   out of the tetrahedralization, keep `Used` = 0 and are counted (NumberOfOutliers, a
 *   warning); no point is deleted. The rule (pcs::FindOutliersAndPiles, shared with
 *   vtkLocalOptimumGrowth): a point's reach is its mean distance to its 8 nearest distinct
 *   points; a point is sparse when its reach is over 4 times the cloud's median reach, and a
 *   sparse point is a far outlier when its reach is over OutlierFactor times the median reach of
 *   its 8 nearest non-sparse points. In a graded sample those are at the edge of the sparse
 *   region, where the density has fallen gradually to the sparse limit; next to an outlier or
 *   clutter they are the surface. A sparse point on a sparse part of the surface is not one
 *   (all its 8 nearest points sparse, a flat disc around it, and half of them passing the same
 *   test; pcsOutliers.h), however much denser the rest of the cloud (a dense patch holding most
 *   of the points made the rest "outliers" before 2026-11-24). A pile of near-coincident
 *   points (a group whose extent is under 1/10,000 of its distance to the rest of the cloud,
 *   pcs::FindPiles) counts as one point with one verdict: piles holding most of the
 *   points made the median reach a pile's and flagged 80 of 1,000 sphere points before
 *   2026-11-24 (now 0); a pile far off the surface is flagged whole (a pile that is not an
 *   outlier is one point, see duplicates above). Points within about 8 surface
 *   reaches (some 20 mean spacings) of the surface are not far outliers (they may be a sparse
 *   part of the surface). Measured (2026-11-23, against VTK's vtkStatisticalOutlierRemoval,
 *   Benchmarks/results/peel.md): no point flagged on the 9 CGAL vertex sets of the benchmark
 *   (their outputs are unchanged), 9 of 405,000 on the vertex sets of CGAL's 94 demo meshes of
 *   32 points or more (handle, anchor, oblong: CAD vertices 10-20 times sparser than their
 *   neighbours; 12 before the sparse-surface exemption of 2026-11-24);
 *   uniform box clutter of 0.1-10 % of the points found at 62-100 %.
 * - ManifoldOutput off: the paper's peeling, one tetrahedron at a time with no topology rule (no
 *   point orphaned); the surface may then have non-manifold edges and vertices.
 * - The triangles are oriented consistently, outward from the solid.
 *
 * Cost: O(n log n) after the tetrahedralization (each tetrahedron is queued a bounded number of
 * times per threshold, and the thresholds are few); the local spacing is one pass over the
 * tetrahedra's edges. The tetrahedra are about 3 per point on a surface sample; points along a
 * curve (a helix, the moment curve: up to n^2 / 2 tetrahedra) have many more, and the filter
 * warns beyond 25 per distinct point (as vtkIncrementalDelaunay3D).
 *
 * Caveat (paper section 3): the threshold is global; on clouds whose density varies a lot, the
 * sparse regions open (holes) or the dense ones keep spurious tetrahedra. ThresholdFactor
 * between 1 and 2 helps, as the paper suggests; the relative measures (LocalSpacingNeighbors)
 * address it for smoothly graded densities.
 *
 * Output: a vtkPolyData with ALL input points and their point data, point data `Used`
 * (unsigned char) and field data NumberOfIterations, FinalThreshold (input units; local spacings
 * with relative measures),
 * NumberOfTetrahedra, NumberOfRemovedTetrahedra (groups included), NumberOfGroupRemovals,
 * NumberOfUnfoldingMoves (rule 6), NumberOfStrutPoints (rule 8),
 * NumberOfTriangles, NumberOfUsedPoints, NumberOfUnusedPoints (outliers and duplicates
 * included), NumberOfOutliers, NumberOfDuplicatePoints (exact and near copies, see above),
 * DelaunayTime and PeelTime
 * (seconds: the tetrahedralization, and everything after it), DelaunayCPUTime and PeelCPUTime
 * (the processor time of the same two parts, std::clock).
 *
 * Under MPI the cloud is gathered on process 0, which computes the surface; the other
 * processes' outputs are empty.
 *
 * @warning A group removal needs a gap at least GroupFactor times the threshold: handles or
 * tunnels narrower than that (relative to the sampling) stay closed. Opening a handle is fragile:
 * measured (2026-11-23) on 6,000 random torus points, genus 1 on 5 of 6 seeds (also with the
 * absolute measure), on 5,000 points of a torus graded 25:1 6 of 6 (2 of 6 with the absolute
 * measure), on 10^5 random torus points 8 of 8 seeds; the knots among CGAL's meshes (knot1,
 * knot2) came out genus 0 before the group start limit (rule 5), now 1 and 2 as their meshes.
 * @warning Caves and webs: on CGAL's mesh vertices the Hausdorff distance is 0.2-4.03 mean
 * spacings (issue 4 asks for 4: met on 8 of 9, camel 4.03). Before the cave limit (rule 4) the
 * triangles farther than 4 spacings from the mesh lay inside the object (caves) on 7 of 8 meshes;
 * after it, outside: webs of tetrahedra left across concave regions (camel: facets 5-9 local
 * spacings, under every group start; rule 7 clears those that go without a change of topology,
 * not camel's: its mesh crosses itself where the hind legs meet at the knees (20 intersecting
 * triangle pairs over about 2.5 x 2 mean spacings), so the legs overlap there, and the web spans
 * the loop they close with the crotch: removing it opens a handle, which the solid of the
 * overlapping legs has (the immersed mesh has genus 0). A genus-0 surface joined at the knees
 * crosses a closed curve through the gap between the thighs that stays 4.25 mean spacings from
 * the mesh, so its Hausdorff distance is at least that (Benchmarks/run_reference_contacts.py;
 * the 4.03 measured is with vtkReconstructionQuality's 3 samples per triangle, 4.45 with 100);
 * a rule that let groups open handles through such webs cleared it, 3.96 at genus 1, but
 * opened spurious handles on the web benchmark), and on knot2 sheets across its holes
 * until the group start limit (rule 5). Noisy samples (Gaussian noise of 0.1 spacing) of spheres,
 * tori and a cube's faces keep their volume since rule 2 follows the widest way in (2026-11-24).
 * @warning Folds: on random samples of a sphere 2.5 % of the triangles face inwards after the
 * unfolding pass (rule 6; normal . radial < 0, 20,000 points: 981 of 39,996; 5,289 without it),
 * 10 % with Gaussian noise of 0.1 spacing (3,868 of 39,438; 6,627 without), 9 % on the noisy
 * torus, none on the exact torus: thin flaps of flat tetrahedra (nearly cospherical points) with
 * both sides on the surface, within 0.05 (exact) / 0.2 (noisy) spacing of the sphere, so the
 * volume and the distances are right but shading shows dark specks (CDT, LOG, greedy and CGAL:
 * 0-2).
 * @warning Open surfaces: the output is the boundary of a solid, so a cloud of an open surface (a
 * scan of one side, a hemisphere, a terrain) comes back closed, with a lid of Delaunay triangles
 * across each opening (10,000 points of a hemisphere: 19,996 triangles, 0 boundary edges). Use a
 * growing filter (vtkLocalOptimumGrowth, vtkCDTAdvancingFront, vtkGreedySurfaceTriangulation)
 * for open surfaces.
 * @warning Relative measures and thin walls: across a wall thinner than the spacing the nearest
 * neighbours include the far side, the local spacing is underestimated and the wall's facets look
 * too large; at ThresholdFactor 1.0 the paper's goblet cup (wall 0.1, about two spacings) comes
 * out closed over every point but zigzagging through the wall near the rim (clean from 1.5, or with
 * LocalSpacingNeighbors 0).
 * @warning Cost (measured 2026-11-24, processor times, load 10-14 on 2 cores; issue 4 asks for
 * 0.5 times the tetrahedralization at 10^6 points): the peel takes 0.53 times the
 * tetrahedralization on 10^6 random sphere points and 0.60 on a torus without the unfolding pass
 * (rule 6), 0.80 on the sphere with it (idle, 2026-11-24; 1.16 before its trials were made
 * local, 0.89 before the single-cell trials from facets and the skipped refusals); on 10^5 points
 * 0.73 (sphere) and 0.84 (torus). It works on a renumbered copy of the tetrahedralization
 * (vertices in insertion order, cells sorted by their newest vertex:
 * pcs::Delaunay3D::RenumberByInsertion; 36 bytes per cell more while the cells are copied), so that
 * the cells and points the queue visits all over the surface are mostly near their neighbours in
 * memory, and prefetches the cells of the next turns. What remains is memory latency: the queue's
 * tests and the walks around edges, the unfolding pass, the local spacing and, on the torus, the
 * group removals. Random spheres of 10^5 points (16 seeds) and 10^6 points come out genus 0.
 *
 * @sa vtkIncrementalDelaunay3D vtkReconstructionQuality
 */
#ifndef vtkPerimeterPeelSurface_h
#define vtkPerimeterPeelSurface_h

#include "vtkPointCloudSurfaceFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

class VTKPOINTCLOUDSURFACEFILTERS_EXPORT vtkPerimeterPeelSurface : public vtkPolyDataAlgorithm
{
public:
  static vtkPerimeterPeelSurface* New();
  vtkTypeMacro(vtkPerimeterPeelSurface, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum FacetMeasures
  {
    PERIMETER = 0,
    AREA = 1,
    CIRCUMRADIUS = 2
  };

  ///@{
  /// Factor applied to the mean exterior facet measure to get the threshold (paper step 4).
  /// Default 1.0; range [0.01, 1000] (the paper uses 1.0-2.0; larger keeps more tetrahedra).
  vtkSetClampMacro(ThresholdFactor, double, 0.01, 1000.0);
  vtkGetMacro(ThresholdFactor, double);
  ///@}

  ///@{
  /// Relative change of the mean exterior measure under which the iteration stops (paper
  /// step 7: 1 %). Default 0.01; range [0, 1].
  vtkSetClampMacro(ConvergenceTolerance, double, 0.0, 1.0);
  vtkGetMacro(ConvergenceTolerance, double);
  ///@}

  ///@{
  /// A fixed threshold in input units (> 0), used instead of the mean x ThresholdFactor; one
  /// peeling pass. Default 0 (automatic); range [0, VTK_DOUBLE_MAX].
  vtkSetClampMacro(Threshold, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Threshold, double);
  ///@}

  ///@{
  /// The measure of a facet: PERIMETER (0, the default, the paper's choice), AREA (1) or
  /// CIRCUMRADIUS (2). Range [0, 2].
  vtkSetClampMacro(FacetMeasure, int, PERIMETER, CIRCUMRADIUS);
  vtkGetMacro(FacetMeasure, int);
  void SetFacetMeasureToPerimeter() { this->SetFacetMeasure(PERIMETER); }
  void SetFacetMeasureToArea() { this->SetFacetMeasure(AREA); }
  void SetFacetMeasureToCircumradius() { this->SetFacetMeasure(CIRCUMRADIUS); }
  ///@}

  ///@{
  /// Largest number of threshold updates (paper step 7). Default 100; range [1, 100000].
  vtkSetClampMacro(MaximumIterations, int, 1, 100000);
  vtkGetMacro(MaximumIterations, int);
  ///@}

  ///@{
  /// With ManifoldOutput: facets larger than GroupFactor x threshold are clearly not surface
  /// triangles; group removals (which open handles) start only at them, and below it a removal
  /// must not show a larger facet (rules 2 and 3 above). A ratio of lengths: squared with the
  /// AREA measure. Default 4.0; range [1, 1000] (1: every refused facet over the threshold
  /// starts a group; large: no handle opens).
  vtkSetClampMacro(GroupFactor, double, 1.0, 1000.0);
  vtkGetMacro(GroupFactor, double);
  ///@}

  ///@{
  /// With ManifoldOutput (rule 3 above): a group of at most 8 tetrahedra that opens a handle is
  /// accepted only when its start facet exceeds HandleFactor x GroupFactor x threshold (squared
  /// with the AREA measure). Default 1.0 (every group start qualifies: the short groups punch the
  /// webs of flat tetrahedra left across concave regions); range [1, 1000]; 2 was the rule
  /// before 2026-11-23 (against tunnels between two dents of dense random spheres).
  vtkSetClampMacro(HandleFactor, double, 1.0, 1000.0);
  vtkGetMacro(HandleFactor, double);
  ///@}

  ///@{
  /// With ManifoldOutput and relative measures (rule 4 above): a tetrahedron whose exterior
  /// facets are all at most as large as an equilateral triangle of perimeter CaveLimit local
  /// spacings is kept when its removal would show the outside a larger facet. Default 9.0 (above
  /// nearly every true surface triangle: a uniform sample's have perimeters of about 3 local
  /// spacings); range [0, 1000]; 0: off (also off with the absolute measure).
  vtkSetClampMacro(CaveLimit, double, 0.0, 1000.0);
  vtkGetMacro(CaveLimit, double);
  ///@}

  ///@{
  /// With ManifoldOutput and relative measures (rule 5 above): once the peel has converged with
  /// GroupFactor x threshold over an equilateral triangle of perimeter GroupStartLimit local
  /// spacings, group removals start at facets over it too, and the peel iterates again. Default
  /// 12.0 (GroupFactor's default times the perimeter of a uniform sample's surface triangle,
  /// about 3 local spacings); range [0, 1000]; 0: off (also off with the absolute measure).
  vtkSetClampMacro(GroupStartLimit, double, 0.0, 1000.0);
  vtkGetMacro(GroupStartLimit, double);
  ///@}

  ///@{
  /// Measure each facet relative to the local spacing of the cloud: divided by the mean, over the
  /// facet's three vertices, of the mean length of each vertex's LocalSpacingNeighbors shortest
  /// Delaunay edges (its nearest neighbours; bounded by 1.5 times their median when one is an
  /// outlier, see above; squared for the AREA measure), so that one ThresholdFactor fits sparse
  /// and dense regions alike. Default 6; range [0, 64]; 0: the paper's absolute measure (also
  /// used whenever Threshold > 0).
  vtkSetClampMacro(LocalSpacingNeighbors, int, 0, 64);
  vtkGetMacro(LocalSpacingNeighbors, int);
  ///@}

  ///@{
  /// Far outliers (see above) are left out of the tetrahedralization and reported: a point
  /// whose reach (mean distance to its 8 nearest points) is over 4 times the cloud's median
  /// reach and over OutlierFactor times the median reach of its 8 nearest points that are not,
  /// unless it lies on a sparse part of the surface (pcs::FindOutliersAndPiles; its table also
  /// gives the piles, see duplicates above). Default 8.0 (no point
  /// flagged on the 9 CGAL vertex sets of the benchmark; 9 of 405,000 on 94 CGAL mesh vertex
  /// sets); range [0, 1000]; 0: off.
  vtkSetClampMacro(OutlierFactor, double, 0.0, 1000.0);
  vtkGetMacro(OutlierFactor, double);
  ///@}

  ///@{
  /// Peel with the sculpting rules and group removals, so that the surface is a closed
  /// 2-manifold (no non-manifold edge or vertex) at every step. Default on; off: the paper's
  /// peeling, which may leave non-manifold edges and vertices.
  vtkSetMacro(ManifoldOutput, bool);
  vtkGetMacro(ManifoldOutput, bool);
  vtkBooleanMacro(ManifoldOutput, bool);
  ///@}

protected:
  vtkPerimeterPeelSurface();
  ~vtkPerimeterPeelSurface() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double ThresholdFactor = 1.0;
  double ConvergenceTolerance = 0.01;
  double Threshold = 0.0;
  int FacetMeasure = PERIMETER;
  int MaximumIterations = 100;
  double GroupFactor = 4.0;
  double HandleFactor = 1.0;
  bool ManifoldOutput = true;
  int LocalSpacingNeighbors = 6;
  double CaveLimit = 9.0;
  double GroupStartLimit = 12.0;
  double OutlierFactor = 8.0;

private:
  vtkPerimeterPeelSurface(const vtkPerimeterPeelSurface&) = delete;
  void operator=(const vtkPerimeterPeelSurface&) = delete;
};

#endif
