/**
 * @class   vtkGreedySurfaceTriangulation
 * @brief   greedy surface triangulation of problem point clouds: well-sampled regions by a 3D
 *          greedy triangulation, badly sampled regions repaired by bridges between islands and
 *          projected hole triangulation.
 *
 * vtkGreedySurfaceTriangulation reconstructs a triangle mesh from the points of any vtkPointSet
 * (its cells are ignored) after Emelyanov & Skala, "Surface Reconstruction from Problem Point
 * Clouds" (paper 001). It is meant for scans whose well-sampled regions are separated by thin or
 * empty ones: a fast greedy triangulation where the sampling is good, then repairs. The steps
 * (paper section 3.2) and the choices made where the paper is silent:
 *
 * - Neighbours: the NumberOfNeighbors nearest neighbours of every point (vtkStaticPointLocator,
 *   threaded with vtkSMPTools). Their distances give the cloud's mean spacing s (mean distance
 *   to the nearest neighbour, field data `MeanSpacing`); every length parameter below is in
 *   units of s, so the parameters do not depend on the cloud's scale. The local uniformity
 *   factor m of section 3 (point data `LocalUniformity`): from the nearest neighbours in order,
 *   a neighbour is admitted when its direction is at least UniformityAngle (a, paper 30 deg)
 *   away from every direction admitted before, until UniformityNeighbors (N, paper 6) are
 *   admitted; m = longest / shortest admitted distance (the formula lost from the paper's text:
 *   its Table 1 reports m = 1.8 to 2.4 in well-sampled regions, which this ratio reproduces).
 *   NaN when fewer than 2 directions are admitted among the neighbours.
 * - Step 1 (section 3.2, Fig. 6): 3D greedy triangulation. Candidate edges join each point to
 *   its neighbours; they are taken by increasing length and an edge is accepted when the
 *   paper's purely topological test passes: no edge gets more than two triangles and no
 *   tetrahedron appears. Triangles are the 3-cycles the accepted edges close; edges left without
 *   triangles are dropped. Two guards are added. An edge that would close an exactly degenerate
 *   triangle (collinear points, exact predicates) is refused. And, with the CrossingTest, an
 *   edge is refused when it crosses an accepted edge in the tangent plane of
 *   its end points (the mean of their unoriented normals, the least-squares planes of each
 *   point and its NumberOfNeighbors nearest points as in vtkPCANormalEstimation, computed by
 *   the shared estimator from the same neighbour table; exact 2D segment tests on the projected
 *   points): the 2D greedy
 *   triangulation's compatibility rule, applied locally. The paper's test alone is meant for
 *   scanner-regular clouds (its Table 1: m about 2); on random samples (m about 5) it leaves
 *   only about 40 % of the points correctly connected after step 2, against 99 % with the
 *   crossing test (5,000 random points on a sphere). The paper allows another step-1 method
 *   for other clouds ("for other cases at the given step another algorithm can be used").
 *   With the crossing test, an edge ab is also refused when it would make a triangle abc
 *   standing across the surface (ours, issue 7), closed by ab or made of ab and an accepted edge
 *   at a or b: its angle at c above 150 degrees, its normal more than 70 degrees from the
 *   unoriented normals of a, b and c, and the nearest points of a, b and c on both sides of its
 *   plane, farther than half of ab. Three points of a sampling line that curves out of the
 *   surface make one: on a torus sampled on a regular (u, v) grid, the circles around the tube
 *   where they are sampled more than about twice as densely as they are apart (and, around the
 *   inner equator of a fat tube, the circles around the axis), whose chords across the tube (or
 *   across the torus's hole) are shorter than the way to the next circle. In the tangent plane
 *   such a triangle projects onto a segment with c on it, a tie that the exact crossing test on
 *   rounded projections cannot decide; step 1 took the chords, closing the tube or the hole with
 *   discs, and the umbrella test then lost the points around them. On 200 such grids (24 to 96 by
 *   12 to 48 points, tube radius 0.25 to 0.7 of the axis radius) 60 results were open and 37
 *   closed with the wrong genus (34 spheres); now 6 are open (bands of lost points where the
 *   paper's test alone left more than AutomaticCorrectFraction of the points correct, so the
 *   crossing test did not run) and none has the wrong genus (Benchmarks/results/greedy.md). The
 *   grids' triangles have angles at c of 166 degrees and more and normals within 1 degree of
 *   perpendicular to their points' normals; "obtuse" and 60 degrees (the first bounds) also
 *   refused ordinary obtuse triangles of noisy clouds (a noisy torus: 599 boundary edges, now
 *   0). The side condition spares the
 *   slivers of a face beyond a sharp edge, where the normals are those of neither face: that
 *   face's points lie in the sliver's plane and the other face's on one side only.
 * - Scan-line sampling (laser-line and LiDAR scans: points 6 to 20 times denser along lines than
 *   across them; not in the paper). There the NumberOfNeighbors nearest of every point lie on its
 *   own line, step 1 took every edge along the lines first and made a few triangles of three
 *   points of one line (a sheet of 16 lines: 3 to 1,143 triangles, 97 to 99.8 % of the points
 *   unused). Where the nearest half of a point's neighbours lie along one line, and so do those of
 *   at least half of its neighbours (the pattern of a region, not of a few points of an ordinary
 *   sample that happen to line up), the point gets the nearest points of the lines beside it as
 *   neighbours and a stretch s along its line (pcs::AddOffLineNeighbors, shared with
 *   vtkLocalOptimumGrowth). Lengths at such points are measured in the sampling's metric:
 *   sqrt(|w|^2 + (w . s)^2) for an offset w, with the larger of the two end points' components (an
 *   edge along a line stays long where one end got no stretch), so that the spacing along a line
 *   counts as the spacing across the lines. Step 1 takes its candidate edges in that length (so
 *   does step 6's 2D greedy triangulation, which joined the points of one line first in 3D
 *   lengths), and refuses, like a degenerate one, a triangle each of whose edges runs along a line
 *   (within 45 degrees of the line at one end): three points of one line, a sliver that the border
 *   lines of a sheet otherwise get. The mean spacing s is the mean distance to the nearest
 *   neighbour in that metric (about the spacing across the lines), so every length parameter
 *   below, from the boundary vectors' radius to the bridge and hole limits, is in units of the
 *   local sampling. A sheet gives the strip triangulation of its lines (2 (N - 1) triangles
 *   between two lines of N points, one boundary loop, every point used), a sphere sampled on
 *   latitude circles a closed genus-0 mesh (the caps inside the first and last circles filled by
 *   step 6). Clouds without such regions are not affected.
 * - Step 2 (Fig. 7, 8): the umbrella test. A point is correct when its triangles form one
 *   closed chain (one open chain at a border), as in the paper, and -- the smoothness condition
 *   of section 3, which defines the well-sampled regions -- the normals of its triangles,
 *   oriented along the chain, deviate by less than MaximumNormalDeviation (paper 90 deg)
 *   pairwise, and the chain projected onto the plane normal to their mean winds once around the
 *   point (each projected triangle positively oriented, decided exactly). Points failing the
 *   test are lost; their triangles are removed and their neighbours tested again until every
 *   remaining point passes. Connected regions of fewer than MinimumIslandTriangles triangles
 *   (but the largest) are dissolved: their points become lost points. The remaining triangles
 *   are oriented consistently (pcs::SurfaceMesh, the topology shared with the other growing
 *   filters) and their boundary loops extracted.
 *   Strips that make a handle (ours, issue 7): step 1 may join the open borders of two sheets that
 *   face each other across a narrow gap (on CGAL's elephant, about 2 spacings) by a strip of
 *   triangles that passes the umbrella test: a fourth handle on a genus-3 surface. Before the loops
 *   are extracted, an edge of two triangles whose end points are boundary points of one loop is a
 *   handle's chord when its two triangles stay connected through their edges once it is cut (the
 *   piece's genus drops: on a genus-0 piece no such edge exists) and it makes more than 30 degrees
 *   with the tangent planes of both end points (each the area-weighted normal of the point's other
 *   triangles; an edge of a sampled surface lies in them up to the curvature over a spacing): its
 *   two triangles are removed and the later steps treat their points. A true handle is cut this way
 *   only where step 2 left a hole across it and an edge there leaves the surface at both ends (the
 *   inner rim of a plate about 2 spacings thick with a through-hole, crossed by a single strip).
 *   The boundary vector of a boundary point points
 *   from the boundary into the triangulated region: the sum of the unit inward perpendiculars of
 *   the boundary edges (each in the plane of its triangle) of the loop points within
 *   BoundaryVectorRadius along the loop (the paper's b, measured along the loop rather than in
 *   space: the paper's mean of the vectors to all neighbours within b mixes both sides of a hole
 *   not much wider than b -- on the 196 loops of a clean 5,000-point sphere after step 2 it
 *   called 17 to 45 holes islands, the edge perpendiculars none). Step 5 uses the vectors of the
 *   point's own two edges.
 * - Regions grown (ours, when GrowRegions is on; stage 2): where the greedy shortest-edge order
 *   fails -- a thin tube sampled in bands a few points around, whose chords across the tube are
 *   shorter than the way to the next band (the tail of CGAL's camel: bands of 16 points, 1.3
 *   spacings thick, 1.6 apart) -- step 1 makes small discs across the tube that step 2 keeps as
 *   small regions and dissolves, and no later step can use their points (they lie in no hole and
 *   beyond the reach of the lost point insertion). Their points are grown again with
 *   vtkLocalOptimumGrowth's expansion (pcs::GrowFront, the shared growth: a seed triangle at a
 *   dissolved point, each front edge expanded by its locally optimal candidate within 60 degrees
 *   of its triangle, the constraints relaxed in stages; its defaults), with the mesh of step 2 in
 *   place: the new parts may join its boundary but its front does not grow. Steps 3 to 8 then
 *   run twice, on the regions of step 2 and on the grown ones, and the grown result is kept
 *   whole when it uses more points without more boundary edges. Otherwise (ours, issue 7) the
 *   two results are compared piece by piece: the triangles one has and the other lacks (same
 *   three vertices) are joined through their vertices into pieces, so that every other triangle
 *   at a piece's points is in both and, once a piece is exchanged, its points have exactly the
 *   grown result's triangles around them. The grown version of a piece is taken when it uses
 *   more of the piece's points without more boundary half-edges at them, and kept when the mesh
 *   then has no more connected components and no larger sum of genera (a piece that would float
 *   apart or make a handle is put back). The shared triangles around a piece take the grown
 *   result's orientation (their components are reversed where a bridge reversed a region in
 *   one result only). A thin part whose tip only the growth reaches (the horns of CGAL's
 *   triceratops) keeps its grown tip when the grown result is left open elsewhere (at the
 *   tail): on the triceratops's vertices 104 -> 65 unused points, on the spool's 132 -> 69
 *   (Benchmarks/results/greedy.md). Counted in NumberOfPiecesExchanged; the other counts but
 *   NumberOfInsertedPoints are those of the result of step 2. The reverse (pieces of the result
 *   of step 2 into a grown result kept whole) was measured and is not done: on the camel's
 *   vertices 27 -> 22 unused points, but with fills across its tail that the fill refinement
 *   had to give 97 new points, and the mean distance to the surface 0.023 -> 0.036 spacings.
 *   After the insertion, grown triangles
 *   hanging by one edge are taken back, and after the caps so are open pieces with grown
 *   triangles of fewer than MinimumIslandTriangles triangles (their points, and in both results
 *   the lost points still free, get one more pass of the lost point insertion into the mesh the
 *   small loops and caps left, and are reported unused when it cannot reach them: on the camel's
 *   vertices 50 -> 31 unused;
 *   a lost point inserted into such a piece is no longer counted in NumberOfInsertedPoints; a
 *   hole fill, loop closure or cap taken back with one stays counted in NumberOfHolesFilled,
 *   NumberOfSmallLoopsClosed or NumberOfEndsCapped: fills made, none taken back on the benchmark
 *   clouds).
 *   On the camel's vertices: 174 -> 50 unused points, completeness (reference within 2 spacings)
 *   0.985 -> 0.998, Hausdorff 6.99 -> 3.64 spacings, closed, 2 components (a closed piece of the
 *   tail apart); the tail's bands are joined to the body, not yet into one tube everywhere.
 *   Costs steps 3 to 8 a second time when islands were dissolved.
 *   Holes around thin parts (ours, issue 7): where step 1 joins the two sides of a part a few
 *   spacings thick (a coarse leg of CGAL's elephant, where 94 % of the lost points have a point of
 *   the far side among their 12 nearest; a thin ear of its armadillo), step 2 leaves a hole whose
 *   lost points wrap around the part and do not project one to one onto the hole's average plane
 *   (the step 5 splits test the loop only), and the 2D greedy triangulation of step 6 cut across
 *   the part: 1.43 and 1.21 spacings from the surface (vtkLocalOptimumGrowth: 0.73, 0.77). So, when
 *   step 2 lost points, a third result is made: the regions of step 2 whose front is expanded into
 *   the lost points by the same growth (each rim grows into its hole), repaired by steps 3 to 8.
 *   After the choice above, its pieces (found as above) are taken where they use as many of their
 *   points with no more boundary half-edges, and have at most half as many triangles made by the
 *   repairs (Stage above 2: fills, swaps, insertions; at least one in the current version): the
 *   surface grown over the points rather than a fill guessed across them. The mesh's
 *   edge-connected components and sum of genera must stay equal, checked once for all the
 *   pieces (all are put back otherwise: a check per piece reads the whole mesh, which tripled the
 *   filter's time on the noisy bunny). Half: on CGAL's rotor (a CAD model's 600 vertices) a
 *   piece of 330 points whose grown version still had 217 repair triangles of 269 and longer
 *   edges was taken with fewer (Hausdorff 9.2 -> 16.3 spacings); the elephant's leg piece has 4
 *   of 96. Elephant and armadillo vertices 1.43 -> 0.47 and 1.21 -> 0.63 spacings, no count
 *   changed (Benchmarks/results/greedy.md). Costs the growth and steps 3 to 8 once more when
 *   points were lost (the filter's time on 10^5 random sphere points 2.09 -> 2.28 s, on the noisy
 *   bunny 0.60 -> 0.79 s).
 * - Step 3 (Fig. 9): hole or island status of every loop. From a loop point P0, P1 is the loop
 *   point farthest from it among those at least a third of the loop away (so that P1 is never a
 *   neighbour of P0 on a thin loop); the dot products (P1 - P0) . I(P1) and (P0 - P1) . I(P0) are
 *   both positive for a hole, both negative for an island. P0 runs over up to 16 points spread
 *   along the loop and the test stops as soon as 3/4 or more of the dot products computed so far
 *   have the same sign (the paper's rule); a product votes only when the angle between P0P1 and
 *   the boundary vector is at least StatusNeutralAngle away from 90 degrees. Without such a
 *   majority, the orientation of the loop decides: it follows the boundary edges of
 *   consistently oriented triangles, so it turns clockwise around a hole and counter-clockwise
 *   around an island seen along their normals; a hole when the loop's vector area and the sum of
 *   the normals of the triangles on its edges are within 60 degrees of opposite, otherwise an
 *   island (left open: the choice that never closes an open surface by mistake).
 * - Step 4 (Fig. 10, 11): bridges (when BridgeIslands is on). For every point of an island
 *   loop, the shortest candidate bridge to each other loop within MaximumBridgeLength (paper: l;
 *   spatial search with the locator) is made. Candidates are taken by increasing length and
 *   admitted when (the conditions are lost from the paper's text; these are the choices): it
 *   leaves both end points away from their regions (against both boundary vectors), neither end
 *   point already has a bridge, it joins loops of different original boundaries (or the same
 *   merged loop, closing a hole between two earlier bridges), it is not a mesh edge, and it
 *   stays at least MinimumBridgeSeparation away from every admitted bridge (no crossing). The
 *   connection order follows the paper's angle rule (auxiliary points at one spacing along each
 *   boundary on both sides of A and B); it fixes the relative orientation of the two regions,
 *   and one of them is reversed when needed (a bridge that would need a region bridged already
 *   to flip is refused). Installing a bridge splices the loops at A and B (the paper's
 *   duplicated points A', B'); afterwards every loop made of original loops is classified again
 *   (step 3), a loop that contains a fragment of a hole is a hole.
 *   Cost: the candidates search the loop points within MaximumBridgeLength of each island point
 *   (pcs::PointBins), the separation test the admitted bridges whose midpoints are within the
 *   candidate's length plus twice MinimumBridgeSeparation (admitted bridges are no longer),
 *   whether two points are on one loop is a label lookup, and the reversals are applied once at
 *   the end: linear in the loop points times the points within reach (a lattice volume, where
 *   the step meets hundreds of small islands: 11.4 -> 1.7 s at 25^3 points, 153 -> 16 s at 46^3).
 *   Bands (ours, issue 7): a band of missing surface around a thin part (a ring of lost points
 *   around a leg, a band cut across a torus's tube) leaves two loops that each go once around
 *   the part; step 3 calls both islands (their votes are neutral, their triangle normals cancel)
 *   and, when one connected piece holds both, no bridge may join them; each was then capped like
 *   a tube's cut end (below), the caps crossing the part (17 to 18 spacings from the surface on
 *   random samples of CGAL's camel and on a torus). Two island loops of one piece, not bridged
 *   yet, bound a band when each runs alongside the other: for at least half of its points the
 *   nearest point of the other loop is within MaximumBridgeLength spacings, in a direction within
 *   30 degrees of the point's tangent plane (the area-weighted normal of its triangles; across
 *   the space between two facing sheets the direction leaves the surface). The band is
 *   triangulated as a strip between the two loops (stage 6, before the other holes): from their
 *   shortest gap, both loops are walked in the same sense around the part and each triangle joins
 *   the current gap to the next point of the loop that gives the shorter new gap; the gaps join
 *   the step 7 swap candidates and the lost points in the band are connected by the lost point
 *   insertion. The strip is not made, and the loops go on as before, when the two loops run
 *   around the part in the same direction (the mesh beside them is not oriented as one band's
 *   sides: the strip would cross the part) or when a gap would leave the tangent plane at one of
 *   its ends by more than 45 degrees; it is refused like a fill when it meets the mesh or would
 *   break the manifold (the loops then stay open).
 * - Step 5 (Fig. 12, 13) and step 6: every hole whose diameter is at most MaximumHoleDiameter
 *   (when FillHoles is on) is split recursively by chords until each piece projects
 *   unambiguously onto its average plane (auxiliary points at AuxiliaryPointDistance, paper:
 *   epsilon, along the boundary vectors must project outside), and each piece is triangulated
 *   with the lost points inside it by the 2D greedy triangulation using 3D lengths
 *   (pcsHoleFilling.h). A piece with more than MaximumHolePoints points is first split by a
 *   diagonal. The lost points of a hole are those within its radius of its centroid, projecting
 *   inside a piece and within half the piece's radius of its plane. A hole whose triangulation
 *   would break the manifold (an edge with a third triangle, a vertex with two fans) is left open.
 * - Fills that cross (ours, issue 7; every fill of step 6, small loops and open ends): a fill is
 *   a guess of missing surface, so it may not pass through or touch another part of the mesh
 *   nor another fill. Every fill is checked before it is added: none of its triangles may meet
 *   (exact triangle-triangle test, pcs::holes::TrianglesIntersect: crossing, touching or
 *   overlapping in a common plane) a mesh triangle whose vertices are all farther than
 *   MaximumBridgeLength spacings from its own -- a part of the surface the sampling does not
 *   join to it; nearer, a contact is a fold at the sampling's resolution (a fill projected flat
 *   grazing the ring beyond a ragged rim, or the other side of a thin part) and is tolerated.
 *   The mesh triangles are found with the point locator (the mesh vertices within the fill
 *   triangle's radius plus 4 spacings; the longer triangles are all tested). The fills of all
 *   the holes of step 6 are made first and checked against each other too: two fills that meet
 *   cap two rims of one gap -- the inner and outer rims of a washer's face sampled only at its
 *   rims, where a disc on the outer rim lies on the inner rim and a disc on the inner rim closes
 *   the through-hole -- and both holes stay open. A fill meeting the mesh is replaced by the
 *   loop's least-dihedral triangulation (below) when that one meets nothing and its largest
 *   dihedral angle is at most MaximumNormalDeviation; otherwise the hole stays open. A hole left
 *   open by these rules is not filled by the later steps either. Counted in
 *   NumberOfFillsRefused (and in NumberOfHolesLeftOpen for step 6). The fairing (below) moves
 *   the new points of a fill afterwards and is not checked again.
 * - Natural borders (ours, issue 7): a scan is often open (a head without its neck, a tube open at
 *   both ends, a vase's mouth), and a faired cap on such a border bulges far from any sample. A
 *   loop is taken for a natural border, and neither step 6 nor CapOpenEnds fills it, when all of
 *   these hold: it is wider than MaximumBridgeLength spacings (a narrower gap is a sampling gap);
 *   its rim is planar (rms distance to its least-squares plane at most 0.05 times its diameter);
 *   the surface meets that plane steeply (the mean |cos| of the angle between the plane's normal
 *   and the tangent planes of the rim points, each the plane of the point and its NumberOfNeighbors
 *   nearest, below 0.5: more than 60 degrees); and no input point lies within half the rim's radius
 *   of its centre (samples inside the rim, e.g. a flat end whose points step 2 lost) nor beyond the
 *   plane, more than 3 spacings from it, within the ball of the rim's radius tangent to the plane
 *   at the rim's centre on the side away from the surface. A removed region of a curved surface
 *   leaves a rim the surface crosses at a shallow angle (a sphere's cap of half-angle a: |cos| =
 *   cos a; on 8,000 random points caps of 20, 40 and 55 degrees are filled, one of 60 degrees, at
 *   the threshold, is left open, a larger one is a bowl's rim), or a rim that is not planar (a ball
 *   removed from a bunny: 0.06 to 0.09 of its diameter); a part cut off from a body by a removed
 *   band (an ear, a capsule's half) faces the body across the gap. Measured on the loops before
 *   filling (mean |cos| from the mesh triangles on the rim): tube ends 0.05 to 0.09, the neck of
 *   CGAL's head 0.34, mannequin-devil 0.36, lion 0.42; removed sphere caps of 20, 40 and 60 degrees
 *   0.93, 0.75 and 0.51. A natural border that is not planar (the silhouette of a statue scanned
 *   from the front) is still filled. Counted in NumberOfHolesLeftOpen when step 3 called it a hole.
 * - Step 7 (Fig. 14): the duplicated points are merged back (the mesh refers to the original
 *   points throughout) and, when SwapBridgeEdges is on, every bridge or chord edge AB whose two
 *   triangles ABC, BAD have |CD| < |AB| is replaced by CD, unless CD is an edge already or the
 *   swap would fold the surface (a new triangle facing against the old ones). Then (ours, issue
 *   7, with SwapBridgeEdges, once after all repairs; counted in NumberOfObtuseSwaps) the edge AB
 *   opposite an obtuse angle at C of a triangle is replaced by CD when the smallest angle of the
 *   two triangles grows (Lawson's local max-min angle swap) and the two new triangles fold by at
 *   most 30 degrees (they stay in the surface), with the same conditions otherwise, for two
 *   triangles of one stage other than hole filling (the stages stay true; the fills are refined
 *   and faired afterwards); new triangles are examined in turn (every swap raises the sorted
 *   list of the mesh's angles, so the pass ends). On a regular sampling step 1 takes three
 *   nearly collinear points with their two short edges and the long one (before the edges to the
 *   next row, about as long): a sliver of up to 178 degrees that the paper's rule does not swap
 *   (|CD| is no shorter than |AB|). A torus on a 200 x 20 grid: smallest angle 0.9 degrees
 *   before, 10.6 after (its grid cells split by a diagonal: 10.5); CGAL's knot1 vertices: 1st
 *   percentile 3.6 -> 25.4 degrees; no count changes (Benchmarks/results/greedy.md).
 * - Lost point insertion (ours, when InsertLostPoints and FillHoles are on; "step 8" in
 *   StepsUsed, run before step 7): the paper connects lost points only through the holes that
 *   contain them; on thin features (legs, ears) and beside the parts cut off by a removed band
 *   many lost points project into no hole piece. Each lost point still unused is connected to
 *   the nearest triangle at its nearest neighbours (pcsPointInsertion.h): the triangle is split
 *   into three when the point projects inside it (exact test), the edge it lies nearest to is
 *   split (its two triangles into four) otherwise, and beyond a boundary edge a triangle is
 *   attached across that edge; a triangle farther than its longest edge is out of reach. The
 *   passes repeat until no point can be inserted, so a point far from the mesh is reached
 *   through its neighbours. After an attachment, the boundary ears at the new point and its two
 *   boundary neighbours sharper than 90 degrees are closed (no zig-zag boundary). The edges of
 *   the split triangles join the step 7 swap candidates.
 * - Small loops (ours, with FillHoles): after the insertion, a boundary loop still open whose
 *   width is at most MaximumBridgeLength, whose diameter is at most MaximumHoleDiameter and
 *   whose connected piece of mesh extends over more than twice that diameter is triangulated
 *   like a hole (steps 5 and 6, with the lost points inside it), whatever step 3 called it: a
 *   gap narrower than a bridge is a sampling gap. The width: for each loop vertex, the distance
 *   to the nearest loop vertex at least a quarter of the loop's length away along the loop; the
 *   lower third of these distances, times sqrt(2) (a circle's width is its diameter, a slit's
 *   about 1.4 times its width, whatever its length). Such loops are small holes whose few
 *   boundary vectors step 3 could not read (noise: the noisy knot's one 7-edge loop, loops of 4
 *   or 5 vertices on the noisy camel), loops reshaped by the insertion, and long narrow gaps on
 *   thin parts sampled in rings (the camel's legs: a loop 20 spacings across and 4.8 wide,
 *   where step 3's farthest-point votes are neutral); the outer border of an open surface spans
 *   its piece and is never one. When the projected fill of such a loop fails (a loop winding
 *   around a thin part does not project simply), the loop polygon is triangulated on its own
 *   vertices by the triangulation that minimises the largest dihedral angle, then the area
 *   (Liepa, SGP 2003, section 3.1: dynamic programming, cubic in the loop size, loops of at most
 *   400 vertices), no diagonal on an existing edge; it is kept when that angle, the mesh
 *   triangles across the loop included, is at most MaximumNormalDeviation. Counted in
 *   NumberOfSmallLoopsClosed, the fallback also in NumberOfSmallLoopsFilledByDihedral.
 * - Open ends (ours, when CapOpenEnds and FillHoles are on, after the small loops): a part cut
 *   off from a closed object by a gap wider than MaximumBridgeLength (an ear behind a removed
 *   band, the lower part of a leg) comes out as a separate piece with open ends, and the cut end
 *   of a tube leaves a loop whose boundary vectors run along the tube, where step 3's votes are
 *   neutral. A loop still open is closed like a small loop when its piece of mesh has at least 4
 *   times the area the loop spans (the norm of its vector area: the flat disc it bounds) and its
 *   diameter is at most MaximumHoleDiameter; the least-dihedral fallback is kept up to 150
 *   degrees (a cap meets the tube's wall at about 90 degrees, more where the cut is ragged; 150
 *   and beyond would lay the cap back onto the mesh). The ratio tells the two kinds of border
 *   apart: the outer border of an open surface spans about the area of its piece (a flat sheet
 *   1, a half cylinder pi / 2, a hemisphere bowl 2), the end of a tube reaching h beyond a
 *   hemisphere of the rim's radius r gives 2 + 2 h / r, and a narrow slit going back along
 *   itself spans almost nothing. A natural border (above: a planar rim the surface meets steeply,
 *   nothing beyond it: a vase's mouth) is not capped, nor the mouth of a well: a loop wider than
 *   MaximumBridgeLength spacings, planar as a natural border's rim (rms distance to its plane at
 *   most 0.05 of its diameter), with no lost point within half its radius of its centre, where
 *   the surface beyond it rises over the outer side of the cap, making an angle of more than 240
 *   degrees with it on the side of the material (the direction in which the surface leaves each
 *   loop edge, perpendicular to the edge in the plane of the K nearest points of its end, towards
 *   its mesh triangle, against the cap's plane, summed over the loop weighted by edge length; a
 *   tube's cut end makes 90 degrees, a hole in a smooth surface about 180, the mouth of a hole
 *   through the object 270 and more, a flared one about 340). The
 *   side of the material is read from the sign of the volume the piece encloses once its loops
 *   are closed by fans, when that volume is at least a quarter of its area times the mean spacing
 *   (a body, not a sheet). Such a cap closes the mouth of a hole whose wall the samples show, and
 *   faired it bulges out of the object (the held-out turbine's flared central hole, the missing
 *   flat ring around its mouth open: 31 spacings from the surface); a well's floor missing in a
 *   scan is left open as well. The caps are fill triangles (stage 6),
 *   refined and faired like the others (FairHoleFills): across a cut the cap bulges to continue the
 *   tube, so the two caps of a narrow cut come close (a capsule of radius 22 spacings cut by an
 *   empty slab 17 spacings wide: 1 spacing apart). Counted in NumberOfEndsCapped, the fallback also
 *   in NumberOfSmallLoopsFilledByDihedral. Parts are not joined back to the body: the hole the part
 *   left in it has been filled by then.
 * - Fill refinement and fairing (ours, when FairHoleFills and FillHoles are on; "9" in
 *   StepsUsed; after Liepa, "Filling Holes in Meshes", SGP 2003, sections 3.2-3.3): step 6
 *   projects a hole on its average plane, so across a region without input points the fill is
 *   flat and made of long triangles between the rim points. A patch of fill triangles (stages 6
 *   and 7, connected through their edges) is treated when one of its triangles has its centroid
 *   farther than 3 sigma from every input point (sigma below; measured: at most 1.95 in the fills
 *   of clean and noisy surfaces, 7.9 to 12.9 across the benchmark's removed regions), so the
 *   small fills among the input points stay as they are. Its triangles are split at their
 *   centroid c while sqrt(2) |c - v| exceeds both sigma_c and sigma_v for each vertex v, sigma of
 *   an input vertex being the mean length of its edges outside the fills and sigma_c the mean of
 *   the triangle's; after each round the edges inside the patch are flipped when not locally
 *   Delaunay (the two opposite angles sum to more than 180 degrees; never onto an existing edge
 *   or into a fold). The new points alone then move to minimise the sum of
 *   d(v)^2 |U(v)|^2 / A(v) over the vertices whose umbrella U(v) = mean of the d(v) neighbours
 *   - v involves them (uniform weights; A(v) a third of the area of v's triangles): the discrete
 *   thin-plate energy, the integral of the squared Laplacian, which d(v) U(v) / A(v) estimates
 *   whatever the edge lengths (conjugate gradients on the normal equations, preconditioned by
 *   their diagonal; two passes, the second with the areas of the first's shape). Every input
 *   point stays fixed: the rim and its outer ring of mesh vertices give the patch the tangent
 *   planes of the surface around it, so a fill across a removed cap bulges like the surface
 *   instead of lying flat. Unweighted (the
 *   plain sum of |U(v)|^2), the fill, coarser than the mesh around it, was flattened against
 *   it: an 8,000-point unit sphere with a 20-degree cap removed came back 0.8 to 1.5 mean
 *   spacings inside the sphere (10 random samples), 0.3 to 1.0 weighted. The triangles keep
 *   their stage; the new points follow the input points in the output.
 * Every closed component is oriented outwards (positive volume).
 *
 * Output (vtkPolyData): all input points and their point data, then the points added by the
 * fill refinement (NumberOfAddedPoints of them, with the point data of the nearest input point),
 * the triangles (consistently oriented, an oriented 2-manifold with boundary), point data `Used` (1
 * for triangle vertices), `Status` (0: correct after step 2, 1: boundary of a correct region, 2:
 * lost and left unused, 3: lost and used by the growth, hole filling or lost point insertion, 4:
 * not triangulated -- a duplicate of another point (an exact copy or a point of a pile, see
 * below), non-finite or a far outlier; every point
 * when the cloud has fewer than 3 distinct finite points; 5: added by the fill refinement),
 * `LocalUniformity` (m);
 * cell data `Stage` (1: step 1 triangle kept by step 2, 2: grown (GrowRegions), 6: hole filling,
 * 7: made by a bridge or chord swap of step 7 (the obtuse-angle swaps keep the stages of the
 * triangles they replace), 8: lost point insertion and its ears); field data `NumberOfTriangles`,
 * `NumberOfLostPoints` (after step 2), `NumberOfIslands`, `NumberOfHoles` (after step 4),
 * `NumberOfBridges`, `NumberOfChords`, `NumberOfHolesFilled`, `NumberOfHolesLeftOpen`,
 * `NumberOfSwaps`, `NumberOfObtuseSwaps`, `NumberOfInsertedPoints`, `NumberOfSmallLoopsClosed`,
 * `NumberOfSmallLoopsFilledByDihedral`, `NumberOfEndsCapped`, `NumberOfFillsRefused`,
 * `NumberOfPiecesExchanged` (GrowRegions), `NumberOfAddedPoints`, `NumberOfUnusedPoints`,
 * `NumberOfDuplicatePoints` (exact and near copies, see below), `NumberOfSkippedPoints`,
 * `NumberOfOutliers`, `MeanSpacing`, and the
 * columns of the paper's Table 1: `NumberOfPoints` (input points), `AverageUniformityInSSR` (mean m
 * over the points of the well-sampled regions, i.e. correct or boundary after step 2),
 * `SSRAreaPercent` (area of the step 1 triangles kept / output area), `SSRPointsPercent`,
 * `StepsUsed` (a string such as "1, 2, 6"), `Seconds`, `PointsPerSecond`.
 *
 * Cost: the neighbour search and the uniformity factors are threaded; step 1 is a sort of about
 * K N / 2 candidate edges and a linear pass; steps 2 to 4 are linear in the mesh and the loops;
 * hole filling is quadratic in the size of each hole piece (bounded by MaximumHolePoints), and
 * each fill is checked against the mesh triangles near it (the long ones looked up by cells of
 * 4 mean spacings); the fill fairing is two conjugate gradient solves over the new points,
 * preconditioned by their diagonal (at most 2,000 iterations each of a pass over them; the whole
 * filter took 0.36 and 0.54 CPU s on the benchmark's damaged bunny, seeds 7 and 8, with 608 and
 * 3,104 points added).
 * Memory about 40 K + 300 bytes per point.
 *
 * @warning
 * Fewer than 3 distinct finite points, or clouds where no triangle can be made (collinear
 * points), give a warning and an output with the points and no triangles. Duplicate points are
 * triangulated once, the copy of smallest id (the others have Used = 0 and Status 4 and are
 * counted in NumberOfDuplicatePoints, with a warning): exact copies, and the points of a pile of
 * near-coincident points (a scanner's repeated returns at one spot, jittered copies; ours,
 * beyond the paper), as in vtkCDTAdvancingFront: a group whose extent is under 1/10,000 of its
 * distance to the rest of the cloud, found on the first 8 columns of the neighbour table
 * (pcs::FindPiles, the definition vtkCDTAdvancingFront's duplicates and the far-outlier rule
 * share; with NumberOfNeighbors under 8, on a table of 8 searched for it). The tolerance is
 * relative to the sampling around the group, no absolute or global distance. A pile
 * triangulated point by point made a blob of needle triangles: 1,000 sphere points and 4 piles
 * of 600 gave 5,322 triangles, 3,328 of them with an edge under 1e-5 of the radius, and 534
 * boundary edges (now 1,996, 2V - 4, closed; Benchmarks/results/robustness.md, "Piles are
 * duplicates in LOG, greedy and the peel"). Non-finite points are skipped, with a warning.
 * Sharp edges (dihedral angles beyond MaximumNormalDeviation) fail the umbrella test and are
 * rebuilt by hole filling, flatter than the original. Holes are filled over the input points
 * by planes; across a removed region of width w on a surface of curvature radius R a flat fill
 * lies up to about w^2 / (8 R) from the original. FairHoleFills (default on) refines and fairs
 * the fills that span regions without input points, adding points: the output then has more
 * points than the input (Status 5 after the input points). On the benchmark's damaged bunny
 * (seeds 7, 8) and armadillo it raised the share of the original surface within 2 spacings of
 * the mesh from 0.977, 0.967, 0.938, 0.943 to 0.986, 0.984, 0.947, 0.958 (0.994, 0.982, 0.950,
 * 0.971 since the umbrellas are weighted by the local area) and lowered the
 * Hausdorff distance from 8.0, 10.8, 16.7, 16.0 to 7.0, 8.4, 13.5, 12.4 spacings (clean and
 * noisy surfaces unchanged, no point added). It cannot restore shape that left no sample: a
 * removed section of a limb leaves two holes, each closed by its own cap, not a tube (the
 * damaged camel 7: 0.797 -> 0.791), and a removed fold is filled smooth. A fill is kept rather
 * than the hole left open because leaving a wide hole open is worse on every measure: on the
 * benchmark's damaged bunny (seeds 7, 8), armadillo, camel and knot, holes left open
 * (MaximumHoleDiameter 20 spacings, 6 on the knot) lowered the share of the original surface within
 * 2 spacings of the mesh (0.977 -> 0.957, 0.967 -> 0.941, 0.938 -> 0.920, 0.798 -> 0.780, 0.980 ->
 * 0.968), raised the Hausdorff distance and added 49 to 741 boundary edges; set MaximumHoleDiameter
 * to refuse fills wider than the sampling justifies. A part cut off by a gap wider than
 * MaximumBridgeLength (an ear behind a removed band) is not bridged: it stays a separate piece,
 * the hole beside it is closed without it, and its own open end is capped (CapOpenEnds). Lost
 * points farther from every
 * triangle than the triangle's longest edge, or whose insertion would fold the mesh, stay
 * unused (Status 2, counted in NumberOfUnusedPoints, with a warning): on CGAL's camel 50 of its
 * 9,770 vertices (0.5 %, its tail and thin legs). Scan lines much denser along than across (every
 * point's NumberOfNeighbors nearest neighbours on its own line) leave almost every point unused.
 *
 * @sa
 * vtkIncrementalDelaunay3D vtkLocalOptimumGrowth vtkCDTAdvancingFront vtkReconstructionQuality
 */

#ifndef vtkGreedySurfaceTriangulation_h
#define vtkGreedySurfaceTriangulation_h

#include "vtkPointCloudSurfaceFiltersModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

class VTKPOINTCLOUDSURFACEFILTERS_EXPORT vtkGreedySurfaceTriangulation : public vtkPolyDataAlgorithm
{
public:
  static vtkGreedySurfaceTriangulation* New();
  vtkTypeMacro(vtkGreedySurfaceTriangulation, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Values of the point data array `Status`.
  enum PointStatus
  {
    CORRECT = 0,
    BOUNDARY = 1,
    LOST = 2,
    LOST_USED_BY_HOLE_FILLING = 3,
    NOT_TRIANGULATED = 4,
    ADDED_BY_HOLE_FILLING = 5
  };

  ///@{
  /**
   * Number of nearest neighbours of each point that give the candidate edges of step 1 and the
   * uniformity factor. Default 12; range [3, 64].
   */
  vtkSetClampMacro(NumberOfNeighbors, int, 3, 64);
  vtkGetMacro(NumberOfNeighbors, int);
  ///@}

  ///@{
  /**
   * Far outliers are reported and left out of the mesh (point data Used = 0,
   * Status 4, field data NumberOfOutliers, counted in NumberOfUnusedPoints, a warning): the rule
   * of vtkPerimeterPeelSurface::OutlierFactor (pcs::FindOutliersAndPiles), same meaning: a point
   * whose reach (mean distance to its 8 nearest points) is over 4 times the cloud's median reach
   * and over OutlierFactor times the median reach of its 8 nearest points that are not, unless it
   * lies on a sparse part of the surface (its 8 nearest sparse too and flat around it: see the
   * peel's docs). A pile of near-coincident points (pcs::FindPiles) counts as one point with
   * one verdict (see the peel's docs); a pile that is not an outlier is triangulated once (its
   * other points are duplicates, see the class docs). With NumberOfNeighbors >= 8 the rule and
   * the piles read the filter's own nearest-neighbour table (pcs::FlagOutliersAndPiles; the
   * table is then made again without the outliers and the piles' duplicates), as
   * vtkLocalOptimumGrowth does; with fewer, one search of 8 neighbours for both
   * (pcs::RemoveOutliersAndPiles; also when OutlierFactor is 0). Default 8.0; range [0, 1000];
   * 0: off.
   */
  vtkSetClampMacro(OutlierFactor, double, 0.0, 1000.0);
  vtkGetMacro(OutlierFactor, double);
  ///@}

  /// Values of CrossingTest.
  enum CrossingTests
  {
    CROSSING_TEST_OFF = 0,
    CROSSING_TEST_ON = 1,
    CROSSING_TEST_AUTOMATIC = 2
  };

  ///@{
  /**
   * Step 1: besides the paper's topological test, refuse an edge that crosses an accepted edge
   * in the local tangent plane, or that makes a triangle standing across the surface (see the
   * class documentation). CROSSING_TEST_OFF (0): the paper's
   * purely topological test; CROSSING_TEST_ON (1); CROSSING_TEST_AUTOMATIC (2, default): steps 1
   * and 2 run with the paper's test and run again when fewer than AutomaticCorrectFraction of
   * the points are correct after step 2, with the crossing test on the edges at the points the
   * first run lost and at their nearest neighbours (elsewhere the paper's test gave correct
   * umbrellas). Range [0, 2].
   */
  vtkSetClampMacro(CrossingTest, int, CROSSING_TEST_OFF, CROSSING_TEST_AUTOMATIC);
  vtkGetMacro(CrossingTest, int);
  void SetCrossingTestToOff() { this->SetCrossingTest(CROSSING_TEST_OFF); }
  void SetCrossingTestToOn() { this->SetCrossingTest(CROSSING_TEST_ON); }
  void SetCrossingTestToAutomatic() { this->SetCrossingTest(CROSSING_TEST_AUTOMATIC); }
  ///@}

  ///@{
  /**
   * Step 1, CROSSING_TEST_AUTOMATIC: the fraction of correct points after step 2 below which
   * steps 1 and 2 are run again with the crossing test. Default 0.9 (the paper reports about 95 %
   * of the points of well-sampled regions correctly connected by its test); range [0, 1].
   */
  vtkSetClampMacro(AutomaticCorrectFraction, double, 0.0, 1.0);
  vtkGetMacro(AutomaticCorrectFraction, double);
  ///@}

  ///@{
  /**
   * N of the local uniformity factor m (paper section 3): the number of admitted neighbour
   * directions. Default 6 (the paper's); range [2, 64] (at most NumberOfNeighbors are examined).
   */
  vtkSetClampMacro(UniformityNeighbors, int, 2, 64);
  vtkGetMacro(UniformityNeighbors, int);
  ///@}

  ///@{
  /**
   * a of the local uniformity factor m, in degrees: a neighbour direction is admitted when it
   * is at least this far from every admitted one. Default 30 (the paper's); range [0, 90].
   */
  vtkSetClampMacro(UniformityAngle, double, 0.0, 90.0);
  vtkGetMacro(UniformityAngle, double);
  ///@}

  ///@{
  /**
   * Step 2: largest angle, in degrees, between the normals of two triangles around a point for
   * the point to be correct (the paper's smoothness condition, section 3, states 90). Default
   * 120: on the bunny with Gaussian noise of a quarter of the mean spacing, 90 leaves 76 % of the
   * points correct, 120 leaves 95 %; clean surfaces are unaffected. Also the largest dihedral
   * angle of the fallback fill of a small loop (see the class documentation). Range [0, 180]
   * (180 disables the smoothness test; the projected winding test remains).
   */
  vtkSetClampMacro(MaximumNormalDeviation, double, 0.0, 180.0);
  vtkGetMacro(MaximumNormalDeviation, double);
  ///@}

  ///@{
  /**
   * Step 2: connected regions of fewer triangles than this (except the largest region) are
   * dissolved after the umbrella test: their points become lost points, triangulated with the
   * hole around them. Default 20; range [0, VTK_INT_MAX] (0 keeps every region).
   */
  vtkSetClampMacro(MinimumIslandTriangles, int, 0, VTK_INT_MAX);
  vtkGetMacro(MinimumIslandTriangles, int);
  ///@}

  ///@{
  /**
   * Step 2: the boundary vector of a boundary point is the sum of the inward perpendiculars of
   * the boundary edges of the loop points within this distance along the loop (the paper's b),
   * in units of the mean spacing. Default 3; range [0, VTK_DOUBLE_MAX] (0: the point's own two
   * edges).
   */
  vtkSetClampMacro(BoundaryVectorRadius, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(BoundaryVectorRadius, double);
  ///@}

  ///@{
  /**
   * Step 3: a dot product of the status test votes only when the angle between P0P1 and the
   * boundary vector differs from 90 degrees by at least this angle, in degrees (boundaries of
   * open surfaces such as a cylinder's rim give angles near 90 degrees either way). Default 15;
   * range [0, 90].
   */
  vtkSetClampMacro(StatusNeutralAngle, double, 0.0, 90.0);
  vtkGetMacro(StatusNeutralAngle, double);
  ///@}

  ///@{
  /**
   * Step 4: build bridges between islands. Default on.
   */
  vtkSetMacro(BridgeIslands, bool);
  vtkGetMacro(BridgeIslands, bool);
  vtkBooleanMacro(BridgeIslands, bool);
  ///@}

  ///@{
  /**
   * Step 4: longest bridge (the paper's l), in units of the mean spacing; with FillHoles, also
   * the largest width of a boundary loop closed after lost point insertion as a sampling gap
   * (see the class documentation). Default 10; range [0, VTK_DOUBLE_MAX].
   */
  vtkSetClampMacro(MaximumBridgeLength, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(MaximumBridgeLength, double);
  ///@}

  ///@{
  /**
   * Step 4: smallest distance between two bridges, in units of the mean spacing (a closer
   * bridge crosses or nearly touches an admitted one and is refused). Default 0.5; range
   * [0, VTK_DOUBLE_MAX].
   */
  vtkSetClampMacro(MinimumBridgeSeparation, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(MinimumBridgeSeparation, double);
  ///@}

  ///@{
  /**
   * Steps 5 and 6: triangulate the holes. Default on. Off stops after step 4 (with
   * BridgeIslands off, after step 3: the well-sampled regions only).
   */
  vtkSetMacro(FillHoles, bool);
  vtkGetMacro(FillHoles, bool);
  vtkBooleanMacro(FillHoles, bool);
  ///@}

  ///@{
  /**
   * Steps 5 and 6: holes wider than this (largest distance between two of their boundary
   * points), in units of the mean spacing, are left open. Default VTK_DOUBLE_MAX (no limit);
   * range [0, VTK_DOUBLE_MAX].
   */
  vtkSetClampMacro(MaximumHoleDiameter, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(MaximumHoleDiameter, double);
  ///@}

  ///@{
  /**
   * Step 5: distance epsilon of the auxiliary boundary points from their boundary points, in
   * units of the mean spacing. Default 0.5; range [0, VTK_DOUBLE_MAX] (0 disables the auxiliary
   * point test: only self-crossing projections are split).
   */
  vtkSetClampMacro(AuxiliaryPointDistance, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(AuxiliaryPointDistance, double);
  ///@}

  ///@{
  /**
   * Step 6: largest number of points (boundary and lost points) triangulated at once; larger
   * hole pieces are split by a diagonal first (the greedy triangulation is quadratic). Default
   * 256; range [16, 100000].
   */
  vtkSetClampMacro(MaximumHolePoints, int, 16, 100000);
  vtkGetMacro(MaximumHolePoints, int);
  ///@}

  ///@{
  /**
   * Step 7: replace a bridge or chord edge AB by the shorter diagonal CD of its two triangles,
   * then (ours) the edge opposite an obtuse angle of a triangle by the other diagonal when the
   * smallest angle of the pair grows and the new pair folds by at most 30 degrees (two
   * triangles of one stage, not of hole filling). Default on.
   */
  vtkSetMacro(SwapBridgeEdges, bool);
  vtkGetMacro(SwapBridgeEdges, bool);
  vtkBooleanMacro(SwapBridgeEdges, bool);
  ///@}

  ///@{
  /**
   * After step 2: mesh the points of the small regions step 2 dissolved again with
   * vtkLocalOptimumGrowth's front expansion (its default constraints, on this filter's
   * NumberOfNeighbors, 12 by default, not vtkLocalOptimumGrowth's 20), beside the regions of step
   * 2; the result is kept when, after steps 3 to 8, it uses more points without more boundary
   * edges, otherwise piece by piece where its piece does so without adding a component or a
   * handle (see the class documentation); and, when step 2 lost points, grow the front of its
   * regions into them too, taking that result's pieces where they use as many points with no more
   * boundary edges and at most half as many repair triangles (see the class documentation). Off:
   * the paper's steps only. Default on.
   */
  vtkSetMacro(GrowRegions, bool);
  vtkGetMacro(GrowRegions, bool);
  vtkBooleanMacro(GrowRegions, bool);
  ///@}

  ///@{
  /**
   * After step 6 (only when FillHoles is on): connect every lost point that no hole contained
   * to the nearest triangle within reach (split it, or attach a triangle across a boundary
   * edge; see the class documentation). Default on.
   */
  vtkSetMacro(InsertLostPoints, bool);
  vtkGetMacro(InsertLostPoints, bool);
  vtkBooleanMacro(InsertLostPoints, bool);
  ///@}

  ///@{
  /**
   * After steps 6 to 8 (only when FillHoles is on): refine the fill patches (hole-filling
   * triangles, stages 6 and 7) that span a region without input points to the edge lengths of
   * the mesh around them, adding points (Status 5, after the input points), and move those new
   * points to minimise the umbrella (thin-plate) energy with every input point fixed, so that a
   * fill across a removed region continues the curved surface around it instead of lying flat
   * (see the class documentation). Off: every fill stays flat and no point is added. Default on.
   */
  vtkSetMacro(FairHoleFills, bool);
  vtkGetMacro(FairHoleFills, bool);
  vtkBooleanMacro(FairHoleFills, bool);
  ///@}

  ///@{
  /**
   * After the small loops (only when FillHoles is on): close a loop still open whose piece of
   * mesh has at least 4 times the area the loop spans -- the cut end of a tube or of a part
   * separated from a closed object, not the border of an open surface (see the class
   * documentation). Off: such loops stay open. Default on.
   */
  vtkSetMacro(CapOpenEnds, bool);
  vtkGetMacro(CapOpenEnds, bool);
  vtkBooleanMacro(CapOpenEnds, bool);
  ///@}

  ///@{
  /**
   * Counts from the last execution (also in the output's field data).
   */
  vtkGetMacro(NumberOfTriangles, vtkIdType);
  vtkGetMacro(NumberOfLostPoints, vtkIdType);
  vtkGetMacro(NumberOfIslands, vtkIdType);
  vtkGetMacro(NumberOfBridges, vtkIdType);
  vtkGetMacro(NumberOfHolesFilled, vtkIdType);
  vtkGetMacro(NumberOfUnusedPoints, vtkIdType);
  vtkGetMacro(NumberOfAddedPoints, vtkIdType);
  vtkGetMacro(MeanSpacing, double);
  ///@}

protected:
  vtkGreedySurfaceTriangulation();
  ~vtkGreedySurfaceTriangulation() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int NumberOfNeighbors = 12;
  double OutlierFactor = 8.0;
  int CrossingTest = CROSSING_TEST_AUTOMATIC;
  double AutomaticCorrectFraction = 0.9;
  int UniformityNeighbors = 6;
  double UniformityAngle = 30.0;
  double MaximumNormalDeviation = 120.0;
  int MinimumIslandTriangles = 20;
  double BoundaryVectorRadius = 3.0;
  double StatusNeutralAngle = 15.0;
  bool BridgeIslands = true;
  double MaximumBridgeLength = 10.0;
  double MinimumBridgeSeparation = 0.5;
  bool FillHoles = true;
  double MaximumHoleDiameter = VTK_DOUBLE_MAX;
  double AuxiliaryPointDistance = 0.5;
  int MaximumHolePoints = 256;
  bool SwapBridgeEdges = true;
  bool InsertLostPoints = true;
  bool GrowRegions = true;
  bool FairHoleFills = true;
  bool CapOpenEnds = true;

  vtkIdType NumberOfTriangles = 0;
  vtkIdType NumberOfLostPoints = 0;
  vtkIdType NumberOfIslands = 0;
  vtkIdType NumberOfBridges = 0;
  vtkIdType NumberOfHolesFilled = 0;
  vtkIdType NumberOfUnusedPoints = 0;
  vtkIdType NumberOfAddedPoints = 0;
  double MeanSpacing = 0.0;

private:
  vtkGreedySurfaceTriangulation(const vtkGreedySurfaceTriangulation&) = delete;
  void operator=(const vtkGreedySurfaceTriangulation&) = delete;
};

#endif
