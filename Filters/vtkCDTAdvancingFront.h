/**
 * @class   vtkCDTAdvancingFront
 * @brief   surface triangle mesh of a point cloud with normals by a constrained Delaunay
 *          advancing front (Huang & Wischgoll).
 *
 * vtkCDTAdvancingFront meshes the points of any vtkPointSet (its cells are ignored) that sample
 * a surface, using a normal at every point. It implements paper 003: Q. Huang, T. Wischgoll,
 * "A Constrained Delaunay Triangle Mesh Method for Three-Dimensional Unstructured Boundary Point
 * Cloud". No point is added (no Steiner points); every triangle joins three input points.
 *
 * Normals: the input's point normals when UseInputNormals is on and the array selected with
 * SetInputArrayToProcess(0, ...) (by default the active point normals) is a 3-component point
 * array; otherwise they are estimated from the points. Each normal is the normal of the
 * least-squares plane of the point and its NormalSampleSize - 1 nearest points (Hoppe et al.'s
 * tangent plane, as vtkPCANormalEstimation: the covariance eigenvector of the smallest
 * eigenvalue). The orientation is propagated along a minimum spanning tree of the graph joining
 * each point to the same nearest points (Hoppe et al.), most certain edges first: two points
 * agree when the normal of one, reflected through the plane bisecting them (the normal carried
 * along a circle through both), has a positive dot product with the other's (cf. Koenig and
 * Gumhold 2009), and an edge costs 1 - |that product| plus the surface variations
 * (3 l0 / (l0 + l1 + l2) of the covariance eigenvalues) of its end points, so the propagation goes
 * around the points whose plane is uncertain. Each connected part of the graph is then turned
 * outwards by a vote of its extreme points along +-x, +-y and +-z (where the outward normal of a
 * closed surface is that axis). vtkPCANormalEstimation's breadth-first traversal (plain dot
 * products, in id order) flipped the far side of any part thinner than a neighbourhood and
 * whatever a wrong normal led to, and one flip by the point farthest from the centroid turned
 * some clouds inside out: CGAL's elephant vertex set had 361 of 2,775 normals inwards, now 5;
 * its cow 2,546 of 2,904 (inside out), now 328.
 * Rows of dense points with sparse gaps (ours): the vertices of decimated meshes lie in dense
 * rows along details, a few spacings apart; where a row bends with the surface (a ring around a
 * body or a leg) the nearest points of its points lie on the row, in a plane through the surface
 * normal, and their plane is off by up to 90 degrees. A point whose (NormalSampleSize - 1) / 2
 * nearest spread along one curve (less than about 0.47 times as far across it as along it) and
 * so do at least half of its nearest (a row, not a chance alignment of a random or noisy sample)
 * gets its plane from its neighbours with its nearest points off the curve on each side
 * (pcs::AddOffLineNeighbors, searched within twice its neighbourhood's radius; the neighbour
 * table and the orientation graph are not changed). CGAL's camel vertex set: normals more than 60
 * degrees off the mesh's 398 -> 183, Hausdorff distance 2.80 -> 1.55 mean spacings; its
 * triceratops 2.17 -> 1.65; the 10^5-point samples and the noisy clouds keep their triangles'
 * quality (Benchmarks/results/cdt.md, "Rows of dense points").
 * Input normals that are zero-length or not finite count as missing: a warning
 * names how many, and those points get estimated normals (oriented like the valid input normals:
 * all estimated normals are flipped when their dot products with the valid input normals sum to
 * a negative value). The normals used are passed to the output when some were estimated (point
 * data `Normals`, or `EstimatedNormals` when the input has a `Normals` array).
 *
 * Rules (section II; each one a parameter below). A triangle is a candidate when all hold:
 * - II.A: its third point lies in the sphere of radius NeighborhoodRadius around the midpoint of
 *   the front edge; among the valid candidates the one closest to that midpoint is chosen (ties:
 *   the smaller point id). The automatic radius is local (ours): NeighborhoodRadiusFactor times
 *   the mean spacing, or times the local spacing of the edge's sparser end point where that is
 *   at least 1.5 mean spacings, so that it grows in the sparse parts, or at most 1/64 of the mean
 *   spacing, so that it shrinks in parts far denser than the rest (see NeighborhoodRadius).
 * - II.C.1: the normals of the front edge's end points each have a positive dot product with the
 *   third point's normal.
 * - II.C.2: |n . N| >= MinimumNormalDot for each vertex normal n and the unit triangle normal N
 *   (no "dangling" triangle).
 * - II.C.3: an edge has at most two triangles, and the third vertices of the two lie on
 *   different sides of the edge plane (through the edge, perpendicular to the existing
 *   triangle), unless their normals point in opposite directions (Fig. 2b, a thin sheet). The
 *   side is an exact orientation sign (a point on the plane is on neither side).
 * - II.D.1: no neighbouring point whose normal has a positive dot product with the three vertex
 *   normals (Fig. 3b/3c) projects, along its normal or its reverse, strictly inside the triangle
 *   at a distance of at most MaximumRayDistance (decided exactly as the crossing of the open
 *   triangle by the point's normal line).
 * - II.D.2: no edge of the mesh whose end-point normals (averaged) have a positive dot product
 *   with the averaged vertex normals (Fig. 4b/4c), projected along its end points' normals onto
 *   the triangle's plane (each within MaximumRayDistance), crosses the open triangle; the crossing
 *   is the case analysis of section II.B (Fig. 1a-g), decided with exact orientation signs on the
 *   projected end points (pcsProjectedTests).
 * - II.E: the vertices are not collinear (exact) and the area is at least MinimumTriangleArea
 *   (default: 1e-6 times the squared longest edge).
 * Two further conditions, implied by the paper's intent, are written down here: the triangle's
 * orientation (inherited from the triangle across the front edge, so that the mesh is
 * consistently oriented) must agree with its vertex normals (N . (n1 + n2 + n3) > 0), and the
 * mesh must stay a manifold: a triangle is only added when each of its edges keeps at most two
 * triangles traversed in opposite directions and each vertex keeps a single fan of triangles.
 *
 * Noise (ours; NoiseBandFactor, 0 for the paper's rules). The points of a scan lie off the
 * surface by a fraction of the spacing, and a triangle between them tilts by up to about
 * atan(2 h / l) for a height noise h and an edge length l: past 60 degrees for the short edges of
 * a random sampling. II.C.2 refused such triangles and the II.D tests were blocked by neighbours
 * just above or below, so the front left many small holes: on 20,000 random points of the unit
 * sphere with Gaussian noise of sigma = 0.2 sqrt(4 pi / N), about 0.4 mean spacings (estimated
 * normals), 2,368 boundary edges and 219 unused points, where CGAL's advancing front leaves 272
 * and 46. The estimated normals are not the cause (the exact radial normals leave 1,784 and 84);
 * II.C.2 is (without it, 608 and 32). Each point gets a noise band: NoiseBandFactor times its
 * height noise, the residual of a quadric height field fitted over its tangent plane to the point
 * and those of its 9 nearest points whose normals are within 60 degrees of its own (a smooth
 * surface is a quadric up to third-order terms, so its curvature is not taken for noise, and the
 * other side of a crease or of a thin part is left out), at most the mean spacing. Two relaxations
 * use it:
 * - II.C.2: a vertex whose normal fails the bound passes when the height of each other vertex
 *   over its tangent plane is within the root sum of squares of the two points' bands (a tilt
 *   the noise alone can give: the triangle lies in the noisy layer of the surface, it does not
 *   dangle across it).
 * - III.C: the last triangle of a hole (its three edges on the front, the only way to close it)
 *   is not blocked (II.D) by a mesh vertex, or a mesh edge with both end points, within the noise
 *   band of its plane (ray parameter t with t^2 <= b^2 + B^2, b the point's band, B the largest of
 *   the triangle's vertices'): the mesh around such a hole overlaps it by less than the noise. A
 *   point not yet meshed still blocks (it is to be meshed, not covered).
 * Same cloud: 579 boundary edges and 37 unused points (exact normals: 433 and 4); at about 0.2 mean
 * spacings of noise 26 and 1 (CGAL 25 and 22). On clean samples the bands are small (the
 * residual of the third-order terms) and the meshes change little (Benchmarks/results/cdt.md).
 * The cylinder of the paper keeps 792 triangles and its 72 hole triangles: its rims' ears stand
 * perpendicular to the surface, far outside its bands.
 *
 * Denoising (ours; LocalPlaneProjection, issue 6). The noise band relaxes the rules, but on a thick
 * noise layer the front still grew two overlapping sheets within it, and the cracks between them
 * were closed by handles or left open (Benchmarks/results/cdt.md, "Noisy clouds of known genus").
 * By default, when the cloud is noisy (pcs::MeasureSamplingNoise on the 9-nearest table: the median
 * height noise of quadric fits above 1/20 of the median local spacing and above the median plane
 * residual, i.e. noise, not curvature), every decision after the normals is made on a copy of the
 * points, each projected onto the least-squares plane of itself and its 19 nearest points
 * (pcs::ProjectOntoLocalPlanes, vtkLocalOptimumGrowth's routine; the table gets the scan-line rows'
 * off-line neighbours first; with input normals only neighbours whose normal is within 90 degrees
 * of the point's, in the decision too, so that the two sides of a plate thinner than a
 * neighbourhood are not merged: two grids 0.3 spacings apart with opposite normals came out as
 * near-coincident points and no triangle; not with estimated normals, whose orientation has wrong
 * patches on noisy clouds: 5 of 32 noisy spheres and tori kept handles or holes that way), copies
 * and piles taking their first copy's projection; the estimated normals are estimated and oriented
 * again on the projected points (kept from the noisy points, their orientation had wrong patches:
 * 371 boundary edges in 5 components on a sphere with noise 0.3 sqrt(area / N), 0 with them). Input
 * normals are kept. The output keeps the input points. Measured (random samples of 20,000 points,
 * noise in units of sqrt(area / N), Benchmarks/results/cdt.md, "Denoising"): unit sphere at sigma
 * 0.2, 23 boundary edges, 3 components, chi -20 -> closed, genus 0, every point; at 0.3, 67
 * boundary edges, 9 components, chi -103 -> closed, genus 0; 10^5 points at 0.2, 109 boundary
 * edges, chi -135 -> closed, genus 0; torus at 0.2, closed with genus 11 (chi -20) -> genus 1; on 8
 * seeds each of spheres at 0.1, 0.2, 0.3 and tori at 0.2, 31 of 32 closed with the true genus (one
 * torus keeps a handle and 4 boundary edges). No clean standard cloud is projected (the triangles
 * of the 27 CGAL vertex sets and the clean spheres and tori of the md5 check are unchanged). Cost
 * (CPU, 10^5 random sphere points, least of 3): the decision on a clean cloud reads 500 points
 * drawn at random (a plane and a quadric each; about 25,000 more only when those are not clearly
 * clean: see pcs::MeasureSamplingNoise), under 1 ms (0.02 s of 0.97 s when every cloud read 25,000:
 * 6-8 % of the filter on the elephant and camel vertex sets); the projection (a 19-nearest search,
 * planes, normals again) 0.2 s; on the noisy one (sigma 0.2) the whole filter takes 1.18 s instead
 * of 1.27 s.
 * Steps (section III):
 * - III.A seeds: in input order, every point not yet meshed starts a seed triangle: its nearest
 *   point (then the next nearest ones, if no triangle is valid, within the budget of
 *   MaximumNumberOfCandidates projection tests for the seed point) gives the first edge, and the
 *   third point is the valid one closest to that edge's midpoint. A point that starts no seed
 *   and is never reached by a front stays unused. Seeds continue until every point is meshed or
 *   rejected.
 * - III.B advancing front: the edges of every new triangle are queued (first in, first out); an
 *   edge with a single triangle is a front edge and is expanded with the best valid third point.
 *   The front edges at the vertices of a new triangle are queued again (an edge that failed may
 *   now close as an ear). A front may touch another front, or itself, at a vertex (a "pinch",
 *   two fans at the vertex, as when the front closes around a cylinder): the next triangles
 *   normally merge the fans.
 * - Rims of real holes (ours, III.B, RefuseRimFans, default off). Where the front runs along
 *   the concave rim of a hole of the object (a bolt hole, a window), the valid point closest to a
 *   rim edge's midpoint is the next rim point across the hole, and each triangle's long new edge
 *   became the next front edge: one rim vertex fanned out to a run of rim points, the edges
 *   growing past the neighbourhood radius (a 60 x 60 grid with a hole of radius 10: 14 slivers
 *   over the hole, edges up to 9 spacings; the hole filling then closed it with edges of 20). With
 *   RefuseRimFans on, a front edge longer than twice the local spacing (the median nearest-point
 *   distance over a point and its 9 nearest, the largest of the three vertices') takes no third
 *   point that makes a longer edge in a triangle with an angle below 15 degrees, so a fan stops
 *   after its first triangle, and the holes of such planes (grid, jittered, rotated, random;
 *   radius 10 and 20 spacings) stay open with HoleFilling on. It is off by default: on clean
 *   random samples it left small holes (10^5 points on CGAL's armadillo: 5 and 12 boundary edges
 *   with estimated and exact normals, elephant 10), and CGAL's real scans keep more of their rims
 *   open (radar 886 -> 1,192 boundary edges; Benchmarks/results/cdt.md, "Rims of real holes").
 * - III.C hole filling (HoleFilling, default on): the front edges left are expanded again with
 *   the relaxed rules of the paper: the neighbourhood radius reduced by HoleFillingRadiusFactor,
 *   plus "the triangle with the adjacent edges at a common vertex" (the ears: the vertices next
 *   to the edge's end points on the front, whatever their distance). The paper removes II.C.2
 *   in this step; here it is relaxed to HoleFillingMinimumNormalDot (default 0.2): without any
 *   bound the ears of the open rims of a cylinder -- triangles perpendicular to the point
 *   normals -- would close them, where the paper's cylinder keeps its 72 hole triangles and 0
 *   hole-filling triangles. Set it to 0 for the paper's rule. One restriction of the ears
 *   beyond the reduced radius: an ear that adds an edge longer than the neighbourhood radius
 *   must have no angle below 15 degrees. Without it a long slit left by the front (on a thin
 *   part, or where the normals turn quickly) was closed by a chain of slivers along it, each
 *   ear's new edge the long side of the next: up to 115 mean spacings long and 11 mean spacings
 *   off the surface on the 10^5-point camel sample, 4.5 to 14 on a sphere with a slit 6 to 12
 *   spacings wide (TestCDTAdvancingFront). Such a slit now stays open (a narrow hole costs
 *   little completeness); a wide hole still closes with long ears of reasonable shape (the
 *   bunny00 vertex set needs ears over 10 mean spacings long). One more relaxation (ours): II.C.1
 *   is not required in this step of a triangle whose two edges at its third vertex are at most
 *   the neighbourhood radius long. Where the surface folds within a few spacings (a rounded rim, a
 *   crease) the normals of the points around a hole left there are more than 90 degrees apart,
 *   and no triangle across it satisfied II.C.1: on the 10^5-point armadillo sample a 6-edge hole
 *   6.6 mean spacings wide on such a fold (vertex normals 54 to 77 degrees from the hole's plane)
 *   stayed open, 2.24 mean spacings from the surface, and was not closed by any other relaxation
 *   (HoleFillingMinimumNormalDot 0, HoleFillingRadiusFactor 1, 200 candidates). The orientation
 *   rule and the relaxed II.C.2 still apply; longer triangles keep II.C.1 (waived for them too,
 *   fills 11 to 26 mean spacings long crossed the camel sample with PCA normals, 3.5 mean
 *   spacings off the surface). Note that II.D.1 ignores a point whose normal disagrees with one
 *   of the vertex normals (Fig. 3b), so such a triangle is checked by II.D.2 mainly.
 * - Handles (ours). A triangle that joins two different front loops of one connected part (it
 *   pinches a front vertex of the other loop, or merges two fans of a vertex) adds a handle. The
 *   front closes around the tube of a torus that way, but on genus-0 clouds it also did so where
 *   it met itself across noise, a second sampling of the surface or a fold of wrong normals, and
 *   the mesh came out closed and manifold with the wrong genus, which nothing flags: the unit
 *   sphere sampled twice, 10,000 random points each, 0.1 mean spacings apart, genus 1; a sphere
 *   whose density grows 1,000-fold from pole to pole, genus 1; a cube and a cone with estimated
 *   normals, genus 1 and 7. Such a triangle is refused when one of the two loops is a hole, at
 *   most 8 edges or shorter than 4 pi mean spacings (vtkLocalOptimumGrowth's rule, its step 4;
 *   a loop around a tube of radius below 2 spacings cannot be told from a hole), and the hole is
 *   closed on its own: genus 0, 0, 0 and 4 on those clouds. Except when both loops go around a
 *   tube (ours, the same exception as vtkLocalOptimumGrowth's step 4): a loop around a thin tube
 *   is as short as a hole, and refusing the join capped the tube at both loops. A loop goes around
 *   a tube when its centroid lies along the normals of the mesh triangles on its edges, as on a
 *   tube's axis: LV = sum over its edges of abs(n . (centroid - m)) / sum of abs(centroid - m)
 *   (m the edge midpoint, n the triangle's unit normal) at least 0.9
 *   (pcs::holes::JoinsLoopsAroundTube; around tubes of 8 to 12 points 0.94 - 1.00, at the holes
 *   of CGAL's vertex sets and of clean and noisy spheres and tori at most 0.77): knot tubes of 300
 *   rings of 8, 10 and 12 points and grid tori of 8 and 10 points around came out genus 0, genus
 *   1 now; the 37 standard clouds are unchanged (Benchmarks/results/cdt.md, "Loops around thin
 *   tubes"). A triangle between two longer loops
 *   is made when the front finds it: deferred until the front stopped, it lost the true handles
 *   of coarse samplings (the loops around a thin tube shrink and close as the front goes on), so
 *   the handles made where the front meets itself across a thick layer of noise remain (Gaussian
 *   noise of 0.3 mean spacings on 10^5 points of a sphere: genus 352 before, 224 after).
 *   CGAL's vertex sets of genus 1 and 2 (knot1, knot2, eight, double-torus-3-holes) keep their
 *   genus; its turbine (genus 11) comes out with 9 handles instead of 11 (Benchmarks/results/
 *   cdt.md, "False handles").
 * - Manifold result: pinches left when the fronts stop are undone (at such a vertex the
 *   triangles of all fans but the largest are removed, `NumberOfRemovedTriangles`) and the holes
 *   this opens are filled again with the III.C rules, pinches no longer allowed. The output has
 *   no non-manifold edge or vertex.
 * - Loops and points left (ours, part of HoleFilling). Where the normals are poor -- estimated
 *   normals of an irregular sampling, such as the vertices of a mesh, dense at details and
 *   sparse on flat parts, whose nearest points lie along a dense line -- the rules above refuse
 *   every triangle across a hole, and the front triangles made around it are tilted or folded:
 *   on CGAL's cow vertex set (PCA normals) 40 of the 41 loops left had a vertex whose normal is
 *   more than 30 degrees off or reversed, and the same cloud with the mesh's normals left half
 *   as many boundary edges. So, after III.C, (1) each usable point that no triangle uses is
 *   connected by the shared kernel pcs::InsertFreePoint at its 9 nearest points (the nearest
 *   triangle split at it, or the edge it lies beyond; a point farther from those triangles than
 *   their longest edge stays unused); (2) each boundary loop of at most 400 edges that passes no
 *   vertex twice is closed by the triangulation of its own vertices of least largest dihedral
 *   angle (pcs::holes::LeastDihedralFill, Liepa 2003; it reads no point normal), kept only when
 *   the centroid and the midpoints of the new edges of every fill triangle lie within 1.5 local
 *   spacings of an input point (the local spacing: the largest of the mean spacing, the mean
 *   nearest-point distance of the loop's vertices and the mean length of the interior mesh edges
 *   at them, the scale at which the surface around the hole is triangulated), no fill triangle
 *   is degenerate or a mesh triangle reversed, and the largest dihedral angle (between fill
 *   triangles, and with the mesh triangle across each loop edge) is at most 170 degrees (not
 *   folded onto a neighbour), and the fill is a small part of the surface it completes: the mesh
 *   triangles reached from its loop edges have more than twice its area
 *   (pcs::holes::FillIsSmallPartOfSurface). This tells the fill of a true hole, a gap in a
 *   surface, from a lid or a pillow: the border of an open patch can only be "closed" by a fill
 *   about as large as the patch, a lid over a bowl or a second layer back to back with a flat
 *   patch (a closed component of no volume); small bowls and saddles (20 to 2,000 random or grid
 *   points) came back closed 49 times of 70 before (PCA normals; 50 with the exact normals),
 *   none after (one boundary loop); (3) step (1) again for
 *   the points the fills left under them; (4) the parts of the mesh without an interior vertex
 *   (lone triangles and strips one triangle wide: seeds that could barely grow among points the
 *   surface passes over or beside, whose border no fill closes) are taken out, their points
 *   connected as in (1), and what could not be connected is put back (pcs::TakeOutStrips,
 *   pcs::PutBackStrips; a point that no triangle takes stays unused and is reported). Before,
 *   such strips were closed by their own border's fill into small closed components (pillows)
 *   beside the main surface, which the boundary-edge figures did not count; with the rule above
 *   they stay open where they are not joined (Benchmarks/results/cdt.md, "Lids and pillows").
 *   The triangles made count as hole filling (`HoleFilled`). An open border stays open: the fill of
 *   the paper's cylinder rims is 2.9 spacings from every point, and a slit 6 spacings wide in a
 *   sphere stays open as before (with 2 local spacings its fill, along the slit, was 1.1 mean
 *   spacings off the sphere). On the vertex sets of CGAL's cow, triceratops and camel (PCA
 *   normals) the boundary edges went from 336, 293, 673 to 38, 19, 49 and the unused points
 *   from 12, 18, 23 to 3, 0, 0 (Benchmarks/results/cdt.md, "Holes left with estimated normals").
 *   Loops of 101 to 400 edges (the bound was 100): where the front leaves a tangle of long thin
 *   triangles (a crease of an irregular vertex set, PCA normals), the loops left are long but
 *   their fills stay within the rules above; the held-out vertex sets of CGAL's femur and man
 *   went from 295 and 662 boundary edges to 149 and 248 (Benchmarks/results/cdt.md, "Loops of up
 *   to 400 edges"). The fill's dynamic programme is cubic in the loop's length, but a wide loop is
 *   refused by its area first, so the longer loops cost little (noisy clouds: 0 to 5 % more CPU).
 *   A loop that no fill closes below 170 degrees because the front folded triangles over it (a
 *   small hole beside a fold of poor normals: every fill would overlap a folded triangle): the
 *   triangles across its edges whose normal is against the loop's vector area (oriented like
 *   the fill) are removed, except one whose removal would leave a vertex without triangles (no
 *   point leaves the mesh), the larger loop they leave is filled by the same rules, and all is
 *   undone unless exactly the loop's edges get closed. Held-out vertex sets ChineseDragon,
 *   triceratops, pig, femur, man: 26, 15, 9, 149, 248 boundary edges before, 18, 11, 0, 136,
 *   233 after, unused points and Hausdorff the same (Benchmarks/results/cdt.md, "Peeling folded
 *   triangles"; TestCDTAdvancingFront.py: a sphere sampled with dense arcs, 4 boundary edges
 *   before, closed after). When that does not close the loop, every triangle across its edges is
 *   removed the same way (a crack along a dense row of points, where the fans on the two sides
 *   skipped different row points: its fills are all slivers). Spheres with 8 dense arcs
 *   (Benchmarks/run_arc_spheres.py, 40 clouds, PCA normals): 311 boundary edges before, 198
 *   after; held-out man 233 -> 222, real building 4,598 -> 4,520 (Benchmarks/results/cdt.md,
 *   "Cracks along dense rows").
 *
 * Scan-line sampling (ours; laser-line and LiDAR scans: points 6 to 20 times denser along lines
 * than across them). There the nearest points of a point lie on its own line: its estimated plane
 * was any plane through the line, the mean spacing (hence NeighborhoodRadius and
 * MaximumRayDistance) the spacing along the lines, and every triangle joined three points of one
 * line (a sheet of 16 lines: hundreds of components, none spanning two lines). Where the
 * (NormalSampleSize - 1) / 2 nearest of a point lie along one line, and so do those of at least
 * 90 % of its nearest points (the pattern of a region, not of a few points of an ordinary sample
 * that happen to line up), the point gets the nearest points of the lines beside it (searched
 * within 8 times its neighbourhood's radius: lines up to about 36 spacings apart with the default
 * 10 points) and a stretch s along its line (pcs::AddOffLineNeighbors, shared with
 * vtkLocalOptimumGrowth and vtkGreedySurfaceTriangulation). Then: the planes and the orientation
 * graph use those neighbours; the mean spacing (`MeanSpacing`, the unit of the automatic
 * NeighborhoodRadius and MaximumRayDistance) and the local spacing measure a point's nearest
 * distance in the sampling's metric sqrt(|w|^2 + (w . s)^2) (the larger of the two end points'
 * components), about the spacing across the lines; candidates (II.A, and the seeds' points) are
 * ranked by that metric's distance to the edge's midpoint, so the next line's points come before
 * the far points of the own line; and a triangle each of whose edges runs along a line (within 45
 * degrees of the line at one end: three points of one line) is refused, except in hole filling,
 * which closes the cap inside a closed line (a pole's circle) with them. A sheet gives the strip
 * triangulation of its lines, a sphere sampled on latitude circles a closed genus-0 mesh. Clouds
 * without such regions are not affected.
 *
 * Output (vtkPolyData): all input points and their point data, plus point data `Used` (1 for a
 * triangle vertex) and `Normals` (when estimated); consistently oriented triangles with cell
 * data `HoleFilled` (1: made by the hole-filling step) and `HoleTriangle` (1: an edge with a
 * single triangle); field data with the columns of the paper's Table 1 (`NumberOfPoints`,
 * `NumberOfTriangles`, `NumberOfHoleFillingTriangles`, `NumberOfHoleTriangles`), its Table 2
 * (`NormalAngleMean`, `NormalAngleDeviation`, `NormalAngleMin`, `NormalAngleMax`: statistics
 * over the used points of the mean angle, in degrees, between a point's normal and the planes of
 * its triangles; 90 means tangent), and `NumberOfFrontTriangles` (seed and front triangles),
 * `NumberOfSeedTriangles`, `NumberOfUnusedPoints`, `NumberOfDuplicatePoints` (exact and near
 * copies, see below),
 * `NumberOfSkippedPoints` (non-finite coordinates; a point whose normal could not be estimated
 * either),
 * `NumberOfOutliers` (far outliers, OutlierFactor),
 * `NumberOfRemovedTriangles` (pinch repair),
 * `MeanSpacing` and `NeighborhoodRadiusUsed`.
 *
 * Cost: each front edge queries the points within NeighborhoodRadius (a bucket grid sized for a
 * surface sample, pcs::BuildSurfaceSampleBins; no vtkStaticPointLocator is built),
 * tests candidates in order of distance until one is valid, and each test visits the points and
 * mesh edges near the triangle: O(N K) for N points and K points per neighbourhood. Duplicate
 * detection, the mean spacing and the normal estimation run in parallel (vtkSMPTools); the front
 * itself is sequential.
 *
 * Work bound (ours): a cloud that is not a sampled surface -- a volume, or clutter denser than
 * the surface around it -- puts several times as many points in every ball, and its front can run
 * away (the 30^3 integer lattice: 310 s and 110,499 triangles for 27,000 points; a sphere of that
 * size takes 0.2 s). The work of the front (the points gathered and the mesh edges listed for its
 * candidates and projection tests, over the seeds, III.B and III.C) is bounded by 10,000 per
 * usable point, and at least 5 x 10^7 (a small cloud's balls reach across much of it). Sampled
 * surfaces of at least 5,000 points take 160 to 3,300 per point (CGAL's meshes, samples and real
 * scans), smaller ones up to 1.1 x 10^7 in all. Past the bound the front and the hole filling
 * stop with a warning that the cloud does not look like a surface; the triangles made so far are
 * kept, the pinch repair runs (a manifold output), the loops left are not closed and the points
 * not reached stay unused. The 30^3 lattice then takes 8 s (Benchmarks/results/cdt.md, "A work
 * bound for volumes").
 *
 * @warning
 * The result depends on the normals: they must be consistently oriented (a flipped patch is
 * meshed separately, the II.C.1 rule stops the front at the flip). Duplicate points are meshed
 * once, the copy of smallest id (the other copies stay unused and are counted in
 * NumberOfDuplicatePoints, with a warning): exact copies, and the points of a pile of
 * near-coincident points (a scanner's repeated returns at one spot; ours, beyond the paper): a
 * group whose extent is under 1/10,000 of its distance to the rest of the cloud, found on the
 * table of the 8 nearest neighbours (pcs::FindPiles, the definition the far-outlier rule of the
 * other filters shares; a separate part of the cloud also has to be under 1/10,000 of the
 * cloud's sampling). The tolerance is relative to the sampling around the group, no absolute or
 * global distance: a dense part of a cloud with a large bounding box keeps its distinct points.
 * A pile meshed point by point made a blob of tiny triangles with random PCA normals: 4 piles
 * of 1,000 points on a 4,000-point sphere took 11 s and left holes, 50 piles of 1,000 on a
 * 5 x 10^4-point sphere more than 150 s (now 0.07 s and about 1.2 s, closed; the normals are
 * estimated again on one point per pile when piles are found; Benchmarks/results/cdt.md and
 * robustness.md). The neighbour tables (normals, scan lines, local spacing, noise band) are read
 * on the distinct positions, so copies do not change the mesh: the cloud with any number of
 * copies of some points gives the same triangles as without them (before, one copy of a seventh
 * of CGAL's camel vertices changed 3,015 of its 19,492 triangles).
 * Points with non-finite
 * coordinates are skipped and counted, with a warning; zero-length or non-finite input normals are
 * estimated, with a warning (see Normals above). Fewer
 * than 3 usable points give a warning and an output without triangles. Under MPI the input is
 * gathered on process 0, which computes the mesh; the other processes output nothing.
 *
 * @warning
 * Measured against CGAL's advancing front on the same clouds (Benchmarks/run_cdt_benchmark.py
 * and CPU times, 2026-11-23/24, loaded 2-core machine; the README gives the tables). CPU time
 * (2026-11-24 at 32584bd, load about 5, results/cdt.md): with the meshes' vertex normals as fast
 * as CGAL on the small irregular vertex set of the elephant (2,775 points) and 1.33-1.89 times
 * faster on the vertex sets of bunny00, armadillo, camel, refined_elephant, fandisk_large, knot1
 * and diplodocus and the 10^5-point samples of the camel and the elephant; with estimated normals
 * 1.33-1.65 times faster on the same clouds but the vertex sets of the camel and the elephant,
 * 1.04 and 1.25 times slower there (a front that refuses more candidates, and the normal
 * estimation; the II.D projection tests of the triangles made are about half of the work).
 * Quality: 0 non-manifold edges and vertices and coverage >= 99 % on every clean cloud; the
 * Hausdorff distance exceeds 2 mean spacings on the 10^5-point samples of the armadillo (2.04, a
 * hole with edges of 7 spacings on a fold) and the camel (2.36: a sharp tip of the mesh is 2.36
 * spacings from the nearest sample point, CGAL 2.38) with exact normals, and with estimated normals
 * on the camel samples (2.36); the camel vertex set went from 2.79 (triangles standing across the
 * surface on the underside of the body, where the PCA planes of its rows were 60-90 degrees off) to
 * 1.55 with the planes of rows (728 of its 9,770 normals more than 30 degrees off the mesh's, 183
 * more than 60), the elephant vertex set from 2.36 to 0.75 with the spanning-tree orientation.
 * Estimated normals are oriented per connected part of the neighbour graph by a vote of its extreme
 * points, which can fail (CGAL's elk vertex set: most normals point inwards, before and after).
 * Noisy clouds (Gaussian noise of 0.4 mean spacing): many front edges and points find no valid
 * triangle (the noise puts neighbouring points inside the candidate triangles' projections); the
 * work per front edge and per seed point is bounded by MaximumNumberOfCandidates, but the filter
 * still takes 3-9 times CGAL's CPU time, leaves holes (coverage 0.94-0.98) and unused points
 * (2-6 %), measured before the noise band (see Noise above; the noisy sphere's boundary edges went
 * from 2,368 to 579, still twice CGAL's).
 *
 * @sa
 * vtkPCANormalEstimation vtkStaticPointLocator vtkReconstructionQuality vtkIncrementalDelaunay3D
 */

#ifndef vtkCDTAdvancingFront_h
#define vtkCDTAdvancingFront_h

#include "vtkPointCloudSurfaceFiltersModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

class VTKPOINTCLOUDSURFACEFILTERS_EXPORT vtkCDTAdvancingFront : public vtkPolyDataAlgorithm
{
public:
  static vtkCDTAdvancingFront* New();
  vtkTypeMacro(vtkCDTAdvancingFront, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Use the input's point normals (the array selected with SetInputArrayToProcess(0, ...), by
   * default the active normals) when present. Default on. When off, or when the input has no
   * such 3-component point array, the normals are estimated with vtkPCANormalEstimation; so are
   * the input normals that are zero-length or not finite (with a warning).
   */
  vtkSetMacro(UseInputNormals, bool);
  vtkGetMacro(UseInputNormals, bool);
  vtkBooleanMacro(UseInputNormals, bool);
  ///@}

  ///@{
  /**
   * Number of nearest points (the point itself included) of the normal estimation, when the
   * normals are estimated: the plane of a point is fitted to them and the orientation follows
   * the graph joining each point to them (see Normals in the class docs). Default 10; range
   * [3, 100] (the estimation's cost grows quickly with it).
   */
  vtkSetClampMacro(NormalSampleSize, int, 3, 100);
  vtkGetMacro(NormalSampleSize, int);
  ///@}

  ///@{
  /**
   * Radius of the sphere around a front edge's midpoint in which third points are searched
   * (section II.A). Default 0: automatic and local, NeighborhoodRadiusFactor times the mean
   * spacing (the mean distance from a point to its nearest distinct point), or times the larger
   * local spacing of the edge's two end points where that is at least 1.5 mean spacings (a
   * point's local spacing: the median of the nearest-point distances of the point and its 9
   * nearest others; the median, so that an isolated outlier does not get a radius across the
   * cloud; 1.5, above the fluctuations of a uniform random sampling: 2 % of its points). Real
   * scans vary in density (CGAL's radar.xyz: nearest-point distances from 0.03 to 1.9, median
   * 0.38), and one radius of 5 mean spacings was about one spacing of the sparse parts, where the
   * front stopped: 1,589 boundary edges in 144 pieces on radar.xyz, now 864 in 35
   * (Benchmarks/results/cdt.md, "Local neighbourhood radius"). Where the radius is so enlarged,
   * a third point farther from the midpoint than the radius of the mean spacing must make a
   * triangle with no angle below 15 degrees (no sliver to a far point); the hole-filling radius
   * (HoleFillingRadiusFactor) and the length beyond which a hole-filling ear must be well shaped
   * follow the same local radius. It follows the local spacing as well where both end points'
   * local spacings are at most 1/64 of the mean (a small object beside a large one, a close-up
   * scan within a distant one): the radius of the mean spacing held thousands of points there,
   * every one of them examined and sorted for each front edge until the examination budget ran
   * out (a unit sphere and a sphere 10^3 times smaller, 10,000 points each: 243 boundary edges
   * and 112 unused points on the small one in 2.8 s, now closed in 0.5 s; 64, so that the dense
   * details of decimated meshes keep the radius of the mean spacing: of the 137 CGAL vertex sets
   * only ALSTOM_TEST4 and mpi have such points, Benchmarks/results/cdt.md, "Parts far denser than
   * the rest"). `NeighborhoodRadiusUsed` reports the radius at the mean spacing. A value > 0 is
   * one global radius. Range [0, VTK_DOUBLE_MAX].
   */
  vtkSetClampMacro(NeighborhoodRadius, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(NeighborhoodRadius, double);
  ///@}

  ///@{
  /**
   * The automatic NeighborhoodRadius in units of the mean spacing, or of the local spacing where
   * the sampling is sparser (at least 1.5 mean spacings) or far denser (at most 1/64 of the mean
   * spacing; used when NeighborhoodRadius is 0).
   * Default 5; range [1, 100]. (With 3, random samplings of a sphere leave holes: the
   * ears of long front edges fall outside the sphere.)
   */
  vtkSetClampMacro(NeighborhoodRadiusFactor, double, 1.0, 100.0);
  vtkGetMacro(NeighborhoodRadiusFactor, double);
  ///@}

  ///@{
  /**
   * Section II.C.2: smallest |n . N| between a vertex's unit normal n and the unit normal N of a
   * new triangle (the cosine of the largest angle between them). Default 0.5 (60 degrees);
   * range [0, 1]. The hole-filling step (section III.C) uses HoleFillingMinimumNormalDot.
   */
  vtkSetClampMacro(MinimumNormalDot, double, 0.0, 1.0);
  vtkGetMacro(MinimumNormalDot, double);
  ///@}

  ///@{
  /**
   * Sections II.C.2 and III.C within the noise band (ours). The noise band of a point is this
   * factor times its height noise (the root mean square residual of a quadric height field
   * fitted over its tangent plane to the point and those of its 9 nearest others whose normals
   * are within 60 degrees), at most the mean spacing. II.C.2: a vertex whose normal fails
   * MinimumNormalDot (or HoleFillingMinimumNormalDot) against a new triangle still passes when
   * the height of each other vertex over its tangent plane is within the root sum of squares of
   * the two points' bands. III.C: the last triangle of a hole is not blocked (II.D) by a mesh
   * point or edge end whose height t over its plane has t^2 <= b^2 + B^2 (b its band, B the
   * largest of the triangle's vertices'). Default 3; range [0, 10]; 0 gives the paper's rules.
   * See "Noise" in the class docs.
   */
  vtkSetClampMacro(NoiseBandFactor, double, 0.0, 10.0);
  vtkGetMacro(NoiseBandFactor, double);
  ///@}

  ///@{
  /**
   * Far outliers (ours, beyond the paper) are left out of the front and reported (point data
   * Used = 0, field data NumberOfOutliers, counted in NumberOfUnusedPoints, a warning): the rule
   * of vtkPerimeterPeelSurface::OutlierFactor (pcs::FindOutliersAndPiles), same meaning: a point
   * whose reach (mean distance to its 8 nearest points) is over 4 times the cloud's median reach
   * and over OutlierFactor times the median reach of its 8 nearest points that are not, unless it
   * lies on a sparse part of the surface (its 8 nearest sparse too and flat around it: see the
   * peel's docs); a pile of near-coincident points counts as one point. The rule reads the
   * first table of nearest neighbours the filter searches anyway (the normal estimation's, or the
   * local spacing's when the normals are given; a search of its own when the cloud has exact
   * copies or NormalSampleSize is under 9), and with outliers the filter goes on without them.
   * Without it, clutter around a surface was meshed into pieces of long triangles, and one point
   * 10^4 radii away gave the front a ball holding every point. Default 8.0; range [0, 1000];
   * 0: off.
   */
  vtkSetClampMacro(OutlierFactor, double, 0.0, 1000.0);
  vtkGetMacro(OutlierFactor, double);
  ///@}

  ///@{
  /**
   * Sections II.D.1-2: a neighbouring point or edge end point blocks a triangle only when its
   * normal ray reaches the triangle's plane within this distance. Default 0: automatic and
   * local, twice the local spacing at the triangle: the largest, over its three vertices, of the
   * mean nearest-point distance over the vertex and its 9 nearest other points, capped at the
   * mean spacing (so at most twice the mean spacing, the bound used before it was made local).
   * Where the sampling is denser than the mean (mesh vertices at details), the bound shrinks with
   * the triangles and so does the neighbourhood each II.D test visits; sparser parts keep the
   * global bound, but a triangle whose three vertices have local spacings (the median used by
   * the automatic NeighborhoodRadius) of at least 2 mean spacings also reaches the surface under
   * it: its bound is at least its reach (largest distance of a vertex to its centroid) times the
   * sine of the largest angle between a vertex normal and its normal, the height of the
   * vertices' tangent planes over it (on a cloud whose density varies by 10^3-10^4, the large
   * triangles of the sparse part otherwise missed the points under them: handles and holes). A
   * value > 0 is one global bound. Range [0, VTK_DOUBLE_MAX].
   */
  vtkSetClampMacro(MaximumRayDistance, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(MaximumRayDistance, double);
  ///@}

  ///@{
  /**
   * Cost bound: each time a front edge is expanded, and for each seed point (over all the first
   * edges it tries), at most this many candidate triangles, the closest to the edge's midpoint
   * among those that pass the cheap rules (II.C, II.E, the manifold rule), are submitted to the
   * projection tests of section II.D; if none passes, the edge stays on the front (the seed
   * point waits for a front to reach it). Default 20; range [1, 100000]. On clean samples the
   * first candidate submitted is accepted for more than 99 % of the front triangles, so the
   * bound matters on noisy clouds (where many edges and seed points find no valid triangle) and
   * for extreme settings (a huge NeighborhoodRadius or MaximumRayDistance, which would otherwise
   * cost O(N) tests per candidate for O(N) candidates). A triangle found blocked by the
   * projection tests is remembered and not tested again (it stays blocked while the mesh only
   * gains triangles; forgotten when the pinch repair removes some), but still counts here, so
   * the result does not depend on that memory.
   */
  vtkSetClampMacro(MaximumNumberOfCandidates, int, 1, 100000);
  vtkGetMacro(MaximumNumberOfCandidates, int);
  ///@}

  ///@{
  /**
   * Section II.E: smallest area of a triangle. Default 0: automatic, 1e-6 times the squared
   * longest edge of the triangle (a shape bound, the same at every scale of a cloud of mixed
   * density). Exactly collinear vertices are always rejected. Range [0, VTK_DOUBLE_MAX].
   */
  vtkSetClampMacro(MinimumTriangleArea, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(MinimumTriangleArea, double);
  ///@}

  ///@{
  /**
   * Section III.B (ours): no fan across the concave rim of a hole of the object. When on, a front
   * edge longer than twice the local spacing takes no third point that makes a longer edge in a
   * triangle with an angle below 15 degrees. Default off (on clean random samples it leaves small
   * holes); turn it on for scans with real holes (bolt holes, windows) to keep them open. See
   * "Rims of real holes" in the class docs.
   */
  vtkSetMacro(RefuseRimFans, bool);
  vtkGetMacro(RefuseRimFans, bool);
  vtkBooleanMacro(RefuseRimFans, bool);
  ///@}

  ///@{
  /**
   * Section III.C: fill the holes left by the advancing front with relaxed rules, then (ours)
   * connect the unused points and close the loops left by the least-dihedral triangulation of
   * their vertices when it stays near the points and is a small part of the surface (not a lid
   * or a second layer over an open patch), and join the points of strips one triangle wide to
   * the surface (see "Loops and points left" in the class docs). Default on. It is meant for the
   * gaps the front leaves, not for the holes of the object: on a grid plane with a hole of radius
   * 4 to 10 spacings it closes the hole; with RefuseRimFans on, a hole of radius 10 spacings or
   * more stays open, a smaller one (radius 3 to 5) is still closed or cut into by the III.C ears.
   * Turn it off to keep every hole the front leaves (see "Rims of real holes").
   */
  vtkSetMacro(HoleFilling, bool);
  vtkGetMacro(HoleFilling, bool);
  vtkBooleanMacro(HoleFilling, bool);
  ///@}

  ///@{
  /**
   * Section III.C, "reduce the proximity neighbouring region": the hole-filling radius is this
   * factor times the neighbourhood radius used. Default 0.5; range [0.01, 1].
   */
  vtkSetClampMacro(HoleFillingRadiusFactor, double, 0.01, 1.0);
  vtkGetMacro(HoleFillingRadiusFactor, double);
  ///@}

  ///@{
  /**
   * Section III.C: the bound of section II.C.2 (|n . N| for each vertex) in the hole-filling
   * step. Default 0.2 (78 degrees); range [0, 1]; 0 removes the rule as the paper does.
   */
  vtkSetClampMacro(HoleFillingMinimumNormalDot, double, 0.0, 1.0);
  vtkGetMacro(HoleFillingMinimumNormalDot, double);
  ///@}

  ///@{
  /**
   * Denoising of the geometry (ours): the triangles are chosen on a copy of the points each
   * projected onto the least-squares plane of itself and its 19 nearest neighbours
   * (pcs::ProjectOntoLocalPlanes; the normals are those of the input points), the output keeps
   * the input points. Off (0): never; On (1): always;
   * Automatic (2, the default): when the cloud is noisy (pcs::MeasureSamplingNoise: the
   * median height noise of quadric fits is more than 1/20 of the median local spacing and more
   * than the median plane residual). Range [0, 2]. See "Noise" in the class docs.
   */
  vtkSetClampMacro(LocalPlaneProjection, int, 0, 2);
  vtkGetMacro(LocalPlaneProjection, int);
  void SetLocalPlaneProjectionToOff() { this->SetLocalPlaneProjection(0); }
  void SetLocalPlaneProjectionToOn() { this->SetLocalPlaneProjection(1); }
  void SetLocalPlaneProjectionToAutomatic() { this->SetLocalPlaneProjection(2); }
  ///@}

  ///@{
  /**
   * Counts from the last execution (also in the output's field data).
   */
  vtkGetMacro(NumberOfTriangles, vtkIdType);
  vtkGetMacro(NumberOfFrontTriangles, vtkIdType);
  vtkGetMacro(NumberOfSeedTriangles, vtkIdType);
  vtkGetMacro(NumberOfHoleFillingTriangles, vtkIdType);
  vtkGetMacro(NumberOfHoleTriangles, vtkIdType);
  vtkGetMacro(NumberOfUnusedPoints, vtkIdType);
  vtkGetMacro(NumberOfDuplicatePoints, vtkIdType);
  vtkGetMacro(NumberOfSkippedPoints, vtkIdType);
  vtkGetMacro(NumberOfOutliers, vtkIdType);
  vtkGetMacro(NumberOfRemovedTriangles, vtkIdType);
  vtkGetMacro(MeanSpacing, double);
  vtkGetMacro(NeighborhoodRadiusUsed, double);
  /// Whether the triangles were chosen on the projected points (LocalPlaneProjection), and the
  /// noise measures of pcs::MeasureSamplingNoise (0 when LocalPlaneProjection is not
  /// automatic; those of its first sample of 500 points when that settled the decision).
  vtkGetMacro(ProjectedOntoLocalPlanes, bool);
  vtkGetMacro(NoiseLevel, double);
  vtkGetMacro(NoiseShare, double);
  ///@}

protected:
  vtkCDTAdvancingFront();
  ~vtkCDTAdvancingFront() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  bool UseInputNormals = true;
  int NormalSampleSize = 10;
  double NeighborhoodRadius = 0.0;
  double NeighborhoodRadiusFactor = 5.0;
  double MinimumNormalDot = 0.5;
  double NoiseBandFactor = 3.0;
  double OutlierFactor = 8.0;
  double MaximumRayDistance = 0.0;
  double MinimumTriangleArea = 0.0;
  int MaximumNumberOfCandidates = 20;
  bool RefuseRimFans = false;
  bool HoleFilling = true;
  double HoleFillingRadiusFactor = 0.5;
  double HoleFillingMinimumNormalDot = 0.2;
  int LocalPlaneProjection = 2; // automatic

  vtkIdType NumberOfTriangles = 0;
  vtkIdType NumberOfFrontTriangles = 0;
  vtkIdType NumberOfSeedTriangles = 0;
  vtkIdType NumberOfHoleFillingTriangles = 0;
  vtkIdType NumberOfHoleTriangles = 0;
  vtkIdType NumberOfUnusedPoints = 0;
  vtkIdType NumberOfDuplicatePoints = 0;
  vtkIdType NumberOfSkippedPoints = 0;
  vtkIdType NumberOfOutliers = 0;
  vtkIdType NumberOfRemovedTriangles = 0;
  double MeanSpacing = 0.0;
  double NeighborhoodRadiusUsed = 0.0;
  bool ProjectedOntoLocalPlanes = false;
  double NoiseLevel = 0.0;
  double NoiseShare = 0.0;

private:
  vtkCDTAdvancingFront(const vtkCDTAdvancingFront&) = delete;
  void operator=(const vtkCDTAdvancingFront&) = delete;
};

#endif
