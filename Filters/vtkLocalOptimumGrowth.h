/**
 * @class   vtkLocalOptimumGrowth
 * @brief   grows a manifold triangle mesh directly on an unorganized point cloud, one locally
 *          optimal triangle per front edge, in O(KN) time (no normals, no tetrahedralization).
 *
 * vtkLocalOptimumGrowth implements the mesh-growing method of paper 004 (Wang, Zhang, Zhou, Wei,
 * "Local Optimum Triangulation for Unorganized Points Cloud", 2013) with the guarantees the
 * paper leaves out: the output is always an oriented 2-manifold (with boundary), every
 * connected part of the cloud is meshed, and small holes are closed.
 *
 * Algorithm.
 * 1. Neighbours ("Materials and methods", K-nearest neighbours and hash table): the K =
 *    NumberOfNeighbors nearest neighbours of every point (ties: smaller index), computed once
 *    on a uniform bin grid, i.e. the paper's hash table, by the project's shared search
 *    (pcs::FindNearestNeighbors: adaptive radius queries on the grid pcs::PointBins, the bins
 *    of VTK's vtkStaticPointLocator; threaded with vtkSMPTools). Unless a locator is set, no
 *    vtkStaticPointLocator is built: the search files the points into its own grid, and the
 *    scan-line search below reuses that grid (filing the coordinates only when it has rows to
 *    extend).
 *    Points are renumbered along a Hilbert curve first (memory locality); duplicates are
 *    merged (exact copies, and the points of a pile of near-coincident points: see the warning
 *    below). Added: unless a locator is set, the grid has about 4 bins per point over the
 *    bounding box instead of VTK's automatic few points per bin -- a surface sample occupies
 *    only a thin layer of the box's bins, so the automatic grid puts tens of points in each
 *    occupied bin.
 *    Measured (1 thread, loaded machine, best of runs): neighbour search on 10^5 points sampled
 *    on CGAL's bunny 0.57 -> 0.50 s, on 10^6 sphere points 5.8 -> 5.1 s, on 10^5 sphere points
 *    unchanged (0.35 s); the triangles are the same. The shared search walks the locator's
 *    buckets itself (see pcsNearestNeighbors.h): on 2 x 10^4 sphere points the filter runs 903
 *    instead of 1166 million instructions (callgrind), the neighbour search 218 instead of 481.
 *    Added, scan-line sampling (laser-line and LiDAR scans: points 5-20 times denser along lines
 *    than across): when the K/2 nearest of a point all lie on its own line (their spread is
 *    one-dimensional, none off the line), its farthest neighbours are replaced by the nearest
 *    points of the lines on either side, within 4 times its K-th distance
 * (pcs::AddOffLineNeighbors, shared with the other filters, see pcsNearestNeighbors.h). At such
 * points constraint 2 (below) measures lengths in the metric of the sampling: the component along
 * the line is stretched by the ratio A of the distance to the nearest point off the line to the
 * distance to the nearest neighbour (averaged over the edge's two ends), so that a triangle between
 * two lines, whose edge along its line is A times shorter than the others, meets the ratios [1/3,
 * 3]. Elsewhere lengths are Euclidean, bit for bit. Measured (Benchmarks/results/
 *    local_optimum.md): 16 lines of 1250 points 12.5 times denser along than across on a wavy
 *    sheet, 6656 one-triangle components (three points of one line each) in 10.2 s CPU before, the
 *    strip triangulation (37,470 triangles between adjacent lines, one boundary loop, every
 *    point) in 0.73 s after; spheres on 40 latitude circles of 500 sin(theta) points (6.2x) and
 *    20 circles of 800 sin(theta) (20x): 149 and 3342 components before, closed, genus 0, after.
 *    On CGAL's mesh vertex sets the triangles are the same except on the camel (one point
 *    triggers: 31 of 19,438 triangles differ, every quality figure the same).
 *    Added, noisy clouds (LocalPlaneProjection; issue 5): the triangles are chosen on a copy of
 *    the points, each projected onto the least-squares plane of itself and its first 19
 *    neighbours of the table (centroid and smallest covariance eigenvector,
 *    pcs::ProjectOntoLocalPlanes, shared with vtkCDTAdvancingFront; vtkGreedySurfaceTriangulation
 *    and vtkPerimeterPeelSurface could use it the same way); the table, the scan-line stretch, the
 *    seed order and the output points are those of the input, and so are the coordinates of the
 *    fold flips and long-edge flips of step 7 (on the projected points they saw no fold, and the
 *    output's folded edges on TestLocalOptimumGrowth's noisy spheres went from 1.1 % to 2.3 %).
 *    By default only when the cloud is
 *    noisy (pcs::MeasureSamplingNoise on the first 9 columns: the median height noise of quadric
 *    fits over the tangent planes above 1/20 of the median local spacing and above the median plane
 *    residual, i.e. noise, not curvature). On a noisy cloud the front grew two overlapping sheets
 *    within the noise layer and the cracks between them stayed open or closed into handles; on
 *    the projected points it sees one sheet (Gaussian noise of rms 0.3 spacings falls to 0.08).
 *    Measured (random unit-sphere and torus samples of 20,000 points, noise sigma in units of
 *    sqrt(area / N), Benchmarks/results/local_optimum.md, "Denoising"): sphere sigma 0.2 94
 *    boundary edges and 23 unused points -> closed, genus 0, every point; sigma 0.3 282 and 26
 *    -> closed, 1 unused; 10^5 points at 0.2 226 and 62 -> closed, 1 unused; torus at 0.2 45 and
 *    14 -> closed, genus 1, every point; on 8 seeds each of spheres at 0.1, 0.2, 0.3 and tori at
 *    0.2 all 32 closed with the true genus, at most 1 point unused. The plane through the
 *    centroid lies inside a curved surface by a fraction of the neighbourhood's sagitta (0.036
 *    spacings on a random sphere of 20,000 points); the output keeps the input points, so that
 *    shows only in which triangles are chosen. No clean standard cloud is projected: the
 *    triangles of the 27 CGAL vertex sets and the clean spheres and tori of the md5 check are
 *    unchanged. (CGAL's femur vertex set, share 0.97, is left alone by the margin: projected, its
 *    mesh went from closed to 54 boundary edges in 2 components.) Two distinct points whose
 *    projections coincide exactly keep their own coordinates. Cost (CPU, 10^5 random sphere
 *    points, least of 3): the decision reads 500 points drawn at random on a clean cloud (about
 *    25,000 more only when those are not clearly clean), under 1 ms (0.013 s of 0.56 s when it
 *    read 25,000); the projection 0.02 s; on the noisy one (sigma 0.2) the whole
 *    filter takes 0.65 s instead of 1.66 s (a front that is not stalled by the noise).
 * 2. Seed triangle (step 1 of the paper): P1 the point of largest x (ties: largest y, then z),
 *    P2 its nearest neighbour, P3 the point of the K-neighbourhoods of P1 and P2 minimizing
 *    |P1P3| + |P2P3| among those meeting constraints 2 and 3; when no P3 exists the next
 *    neighbour is tried as P2 (the paper's "else go to step (2)"), then the constraints relaxed
 *    (see below), then the next extreme point. Added: with the nearest free neighbour as P2,
 *    constraint 2 is widened by the sampling's anisotropy at P1 and P2 (the factor f of step 3
 *    (2), with A alone): on scan lines 3 to 6 times denser along than across that neighbour lies
 *    on P1's line and the next line is out of [k1 d, k2 d], and the P2 farther along the line
 *    made a seed over a line's point (a sliver of three points of the line, or an edge skipping
 *    one) from which no front could grow. The seed is oriented with its normal towards +x
 *    (outwards at the x-extreme point of a closed surface). When the front dies, a new seed is
 *    taken the same way among the points still unused, so every connected part is meshed.
 *    Added, other sheets (ours): P2 is at most 4 times as far from P1 as P1's nearest neighbour,
 *    used or not (lengths of constraint 2). A point the growth left unused among meshed
 *    neighbours has its nearest free ones on another sheet: its seed triangle stood across the
 *    gap between two sheets a few spacings apart (concentric spheres 2.8 mean spacings apart,
 *    one cloud in six); such a point is left to the orphan insertion (step 5). With 3 (the
 *    paper's k2) instead of 4, CGAL's spool vertices kept 29 points unused instead of 12.
 * 3. Expansion (step 2): each front edge a->b (a boundary edge of triangle (a, b, y), kept in
 *    a FIFO queue) is expanded by one candidate c taken from the K-neighbourhoods of a and b
 *    (plus the front neighbours of a and b), giving the triangle (b, a, c). A candidate must
 *    meet the paper's constraints:
 *    (1) the angle between the normals of (b, a, c) and (a, b, y) is at most
 *        MaximumNormalAngle (paper: [0, pi/3], 60 degrees);
 *    (2) the distance from c to the edge, measured to each end point (the lengths |ac| and
 *        |bc|), lies in [MinimumEdgeRatio d, MaximumEdgeRatio d] with d = |ab| (paper: k1 =
 *        1/3, k2 = 3). Measuring to the end points rather than to the edge's line bounds the
 *        edge-length ratio of every new triangle; a point close to the middle of the edge
 *        stays a candidate, so it is meshed instead of being covered by the triangle.
 *        Added, anisotropic samplings: when the triangle (a, b, y) is itself more elongated than
 *        the ratios allow (elongation E = longest / shortest edge above 1 / k1) and so is the
 *        sampling at a and b (A, the distance to the nearest neighbour off the line through the
 *        point and its nearest neighbour -- more than 45 degrees from it -- over the distance to
 *        that nearest neighbour, above 9/4 at both and at their nearest points off their lines:
 *        lines next to lines), the Euclidean lengths may also lie in [k1 d / f, k2 d f], f = 4/3
 *        k1 min(E, A) within [1, 2] (at most the first relaxation level of step 4), for a
 *        candidate on such lines too: the new triangle may be as elongated as the one it
 *        expands and as the sampling, with a margin of 4/3. On scan lines A = 3 to 6 times
 *        denser along than across (below 5 to 6 the stretch of step 1 does not see them) every
 *        triangle between two lines has an edge along a line A times shorter than its others;
 *        with the ratios alone every front edge waited for the relaxed stages, and an edge
 *        across the lines skipped a line's point (closer than d / 3) for the next one, leaving
 *        that point to a sliver along the line, standing across the surface, which no front
 *        edge could expand. Measured (Benchmarks/results/local_optimum.md, task loganiso): unit
 *        spheres on latitude rings 3.5 and 4 times farther apart than their points, 20,000
 *        points, 2,551 and 2,429 components before, closed, genus 0, one component after; at
 *        ratios 3 to 5, 5,000 to 80,000 points, clean or with noise of a tenth of the spacing,
 *        one component and at most 70 boundary edges (one cloud keeps a closed tetrahedron of 4
 *        points besides). The widening (here and for the seeds, step 2) applies only to clouds
 *        sampled in scan lines or on a regular grid: when at least a third of the points of a
 *        regular subsample (every 8th) are on lines next to lines (ours). Applied wherever it
 *        could, it left 20-30 % more boundary edges on mesh vertex sets with a few rows of points
 *        (CGAL's camel 89 -> 108, man 373 -> 475); with the gate those are unchanged (3 and 9 %
 *        of their points on lines; no CGAL vertex set or real scan of the standard clouds is
 *        between 26 %, turbine, and 81 %), and of the 21 standard clouds only rotor changes, a
 *        600-point CAD vertex set with 81 % of its points on rows: 170 -> 223 boundary edges,
 *        Hausdorff 7.38 -> 7.36 spacings. A torus sampled on a regular (u, v) grid of n x n
 *        points has cells (R + r cos v) / r times longer than wide; with a tube radius r of 0.45
 *        to 0.54 times the ring's R, 36 to 48 % of its points are on such lines, and the cells
 *        of its outer band, 2.8 to 3.2 times longer than wide, need the widening: the diagonal of
 *        such a cell is more than 3 times its short side, which is then no candidate to complete
 *        the cell, and the front made triangles skipping rows instead. With half as the bound
 *        (before), 21 of 24 such tori (n = 24 to 72, r = 0.45 to 0.54) were not closed over every
 *        point with genus 1, 0 now (Benchmarks/results/local_optimum.md, task gridlog).
 *        vtkGreedySurfaceTriangulation's growth (pcs::GrowFront) keeps the paper's ratios;
 *    (3) the angles of (b, a, c) at a and at b are at most MaximumBaseAngle (paper: the
 *        projection of c falls on the edge, 90 degrees; default 120 here, since 90 leaves many
 *        front edges of a random sampling without any candidate);
 *    (4) an edge has at most two triangles and interior points (whose umbrella is closed)
 *        are excluded -- with the manifold rules below.
 *    The local-optimality score (the paper does not give one): among the admissible candidates,
 *    the one whose circle through a, b, c contains no other admissible candidate, the circles
 *    taken in the plane of (a, b, y) -- the Delaunay choice in the local tangent plane, decided
 *    with the exact incircle predicate on the projected points (ties: smaller |ac| + |bc|, then
 *    smaller index). It maximizes the smallest angle locally and never leaves a candidate
 *    inside the new triangle. Flat candidates -- whose triangle bends by at most half of
 *    MaximumNormalAngle (30 degrees by default) against (a, b, y) -- come first: with
 *    RelaxConstraints on, the first expansion of a front edge considers only them, and an edge
 *    without a valid flat candidate waits until the front has stalled (step 4); from then on
 *    the choice is made among the flat candidates first, among the others only when none of
 *    the flat ones gives a valid triangle. On a sheet thinner than about one spacing (an ear)
 *    the points of the opposite side are admissible too -- their triangles bend by 40 to 60
 *    degrees -- and in the projection they are mixed with the points of this side, so the
 *    plain choice jumped between the sides and left folded holes. Measured (CGAL mesh vertex
 *    sets, boundary edges, default parameters): with the preference alone armadillo 117 -> 20,
 *    elephant 207 -> 82, camel 511 -> 394, diplodocus 48 -> 30, fandisk_large 20 -> 10; with
 *    the flat first stage as well armadillo 12, elephant 30, camel 319, diplodocus 54,
 *    fandisk_large and knot2 closed (39 before), and random tori not closed with the right genus
 *    1 of 120 instead of 4 (Benchmarks/results/local_optimum.md).
 *    The chosen triangle is then validated, and the next best taken if it fails:
 *    - topology (pcs::SurfaceMesh, the front/edge structure shared with vtkCDTAdvancingFront
 *      and vtkGreedySurfaceTriangulation): consistent orientation, at most two triangles per
 *      edge, no vertex with a second fan;
 *    - no overlap with the mesh nearby, decided with exact orientation predicates on the points
 *      projected onto the plane of (a, b, y): the new triangle lies in the free angle between
 *      the front edges at each of its vertices already meshed, its new edges cross no front
 *      edge of the neighbourhood, and no point of the neighbourhood lies in the closed
 *      triangle (but a point whose projection is exactly a vertex's does not block when the
 *      new triangle lies in the plane of (a, b, y) and the point off it, both exact, unless the
 *      triangle bridges two parts of the front: the point is then on the normal through that
 *      vertex, as on a box sampled on a grid, where the points beyond an edge project onto the
 *      edge's points and left them unused). Points and front edges of another sheet are
 *      ignored: points farther from the triangle's mean height than its longest edge, front
 *      edges whose triangle faces the other way. (Tried and dropped: also ignoring meshed
 *      points whose triangles all face the other way. It left 3 to 22 % fewer boundary edges on
 *      CGAL's camel, elephant, cow, armadillo and man vertices, but more on 10^5 samples of the
 *      armadillo (158 -> 240) and the elephant (66 -> 148), and let a triangle cut across the
 *      elephant's trunk tip, 3.1 mean spacings off the surface: a strongly curved tip looks
 *      like another sheet to that rule.)
 *    Front closing: when the chosen point is the front neighbour of a or b, the triangle is an
 *    ear and closes the angle between two front edges. When it is another front vertex (two
 *    parts of the front meet, e.g. around the tube of a torus), the triangle would pinch that
 *    vertex; it is kept only together with the ear that removes the pinch at once (on either
 *    side, under the same rules), otherwise it is taken back. Two parts grown from different
 *    seeds with opposite orientations are made consistent first (one part is reversed).
 *    The expansion and the deferred edges of step 4 are shared with vtkGreedySurfaceTriangulation
 *    (pcs::GrowFront, pcsFrontGrowth.h: the growth from a given mesh and seed points).
 * 4. Deferred edges and relaxation: a front edge without a valid candidate is set aside and
 *    retried when the front has stalled and its neighbourhood (its ends and their K nearest)
 *    has changed; a retry looks only at the edges near the vertices touched since the previous
 *    one (through the reverse K-nearest table), so its cost follows what changed, not the
 *    number of edges set aside (scan lines that stall the front thousands of times stay
 *    linear). When nothing else can progress and RelaxConstraints is on (added), the edges set
 *    aside are retried in stages before a new seed is planted: with every candidate (the first
 *    stage had only the flat ones, step 3), then with constraint 2 relaxed: first by a factor 2
 *    ([MinimumEdgeRatio / 2, 2 MaximumEdgeRatio]) -- anisotropic samplings such as the rings
 *    around the poles of a latitude-longitude sphere need it --, then without the lower bound,
 *    where constraint 1 measures the candidate's height against a distance to the edge of at
 *    least d / 2 (a point very close to the edge, whose needle triangle has a normal dominated
 *    by the curvature, is admitted by its height) -- but not a point of another sheet, one the
 *    front has not reached (ours): a free point more than 1.5 local spacings (the mean of a's and
 *    b's mean distance to their 6 nearest) off the plane of (a, b, y), none of whose K nearest at
 *    its own level (less than half its height from it along that plane's normal) has a triangle.
 *    The long front edges of the last holes of a closed sheet (3 to 4.5 mean spacings) took the
 *    points of a sheet 2.8 spacings below that way, their triangles standing across the gap, and
 *    grew the other sheet from there: two concentric random spheres of 10,000 points each
 *    (radii 1 and 0.9) came out as one surface on 20 clouds of 20 (numpy samples,
 *    Benchmarks/results/local_optimum.md, task logsharp), as two closed spheres on 20 of 20 now
 *    (with the seed rule of step 2; on 5 of 6 clouds of TestSeparateSheets' generator: the sixth
 *    keeps 6 triangles across the gap, not made by this rule; not diagnosed further). The
 *    threshold keeps the needles the rule is for: without it (a free point with no meshed
 *    neighbour at its level is enough), CGAL's bull, camel, man, turbine, rotor and elk vertex
 *    sets got 18 to 49 more boundary edges and the femur's closed mesh split into three pieces
 *    (triceratops 74 -> 54 boundary edges, the one gain); with it, of the 37
 *    clean and noisy standard clouds 9 change (camel vertices 124 -> 128 boundary edges, elk 101 ->
 *    102; with the seed rule also spool 315 -> 262 and 19 -> 12 unused points, rotor, lion and
 *    triceratops 1 or 2 points more unused). At that last level an ear (the candidate is
 *    the front neighbour of a or b) may also exceed constraint 3 -- its angle at the shared end
 *    is the front's own angle there, close to 180 degrees at every vertex of a thin sliver of
 *    unmeshed surface left where two fronts meet almost along a line -- if its normal is within
 *    MaximumNormalAngle of both triangles it closes between and its new edge is at most 3 local
 *    spacings long (the mean of its ends' mean distances to their 6 nearest neighbours) or the
 *    sliver is there: a candidate point lies across the new edge, within the sphere on it as
 *    diameter. On an open border (a scan's edge, nothing beyond the front) such ears otherwise
 *    followed each other, each new edge up to 2 MaximumEdgeRatio times the one it expanded, and
 *    cut chords across the border up to 153 h long (h = sqrt(area / N); random samples of a wavy
 *    square: Benchmarks/results/local_optimum.md, task logrim). A bridge made after the first stage
 * may not join two different front loops of one part (that would add a handle: there it came only
 * from near-contacts of the front with itself, which folded the mesh over). At the first stage such
 * a bridge closes the front around a tube (a torus), but not when either loop is a hole: at most
 * max(3, MaximumHoleEdges) edges, or shorter than 4 pi mean spacings (the loop around a tube of
 * radius below 2 spacings, which step 6 cannot tell from a sampling gap either). A handle to a hole
 * jumps across the surface; the hole is closed on its own instead. On CGAL's mesh vertex sets each
 * handle of a wrong genus came from such a first-stage bridge, made between two loops 1-3 spacings
 * apart in space (temporary trace): armadillo loops of 3 and 5 edges (8.7 and 14 spacings long),
 * diplodocus 9 and 13 edges (4.1 and 19.8 spacings), camel three (the shortest loops 4, 5 and 14
 * edges). The true handles of the elephant join loops of 14 to 64 edges, 21 spacings long or more.
 * Exception (ours, extending the same rule): two loops that both go around a tube are joined,
 * whatever their length -- a loop around a thin tube is as short as a hole (a knot tube of 12
 * points around: loops of 12 edges, 0.96 of the bound), and refusing the join capped the tube at
 * both loops (genus 0). A loop goes around a tube when its centroid lies along the normals of the
 * mesh triangles on its edges, as on a tube's axis: LV = sum over its edges of abs(n . (centroid -
 * m)) / sum of abs(centroid - m) (m the edge midpoint, n the triangle's unit normal) is at least
 * 0.9 (pcs::holes::JoinsLoopsAroundTube; joins around tubes of 8 to 12 points: 0.94 - 1.00; the
 * joins refused on CGAL's vertex sets and on clean and noisy spheres and tori: at most 0.77, the
 * centroid of a hole lying in the surface beside its rim). A knot tube of 300 rings of 12 points
 * and a grid torus of 24 rings of 8 points, each turned by half a step, come out genus 1 (genus 0
 * before; Testing/Cxx/TestThinTubes.cxx); the 37 clean and noisy standard clouds are unchanged
 * (Benchmarks/results/local_optimum.md, "Loops around thin tubes").
 *    Constraint 4 and the overlap tests are never relaxed. Measured with
 *    Benchmarks/run_local_optimum_closure.py on random (Poisson) samples of 2,000, 5,000, 10,000
 *    and 20,000 points, 30 seeds each, counting the runs not closed over every point with the
 *    right genus: spheres 8 of 120 before these two rules and the orphan rule of step 5 (sliver
 *    holes of 9 to 11 edges, one unused point), 0 of 120 after; tori 21 of 120 before, 4 of 120
 *    after (two extra handles made at the strict level, loops of 5 and 10 edges left).
 * 5. Orphans (added): a free point that the growth left under a triangle (within the projection
 *    of a triangle of its neighbourhood, or near one of its edges, and closer to its plane than
 *    its longest edge) is inserted by splitting that triangle into three, or the two triangles
 *    of the nearest edge into four; beside a boundary edge (its projection falls just across
 *    it), by making the triangle that edge lacks. A point exactly on an edge in space (decided
 *    exactly; points on lattice lines) splits that edge: the two triangles into four, or, on a
 *    boundary edge, its triangle into two; no new triangle may have zero area (a point that
 *    would need one stays unused). A lone triangle (a seed that could not grow) is taken out
 *    first and its points inserted the same way; it is restored when none of them could be.
 *    Then each other separate piece of at most 16 triangles (smallest first; no vertex shared
 *    with another piece) is taken out the same way, and kept out when at least three quarters
 *    of its points could be inserted (the others stay unused); otherwise the insertions are
 *    undone and the piece is put back as it was (a small object on its own). On noisy scans a
 *    seed planted among the points the growth left in the noise closed into a tiny polyhedron
 *    (4 to 9 points) lying within the surface's noise layer: a sphere with Gaussian noise of
 *    0.2 mean spacings, 20,000 points, came out in 4 to 11 pieces (10 random clouds), one piece
 *    now (0 to 2 more unused points); at 0.3 spacings 9 to 24 pieces, one now in 9 of 10 (0 to
 *    6 more unused points). CGAL's mesh vertex sets lose most of their small pieces (man 19 -> 5,
 *    lion 7 -> 2, femur 5 -> 1, camel 9 -> 4 with 89 -> 95 boundary edges; Hausdorff distances
 *    unchanged; Benchmarks/results/local_optimum.md).
 * 6. Holes (added): the boundary loops of at most MaximumHoleEdges edges are closed with the
 *    project's shared hole triangulation (paper 001 steps 5-6: projection on the loop's mean plane,
 *    chord splitting, 2D greedy triangulation, free points inside used), kept only when every
 *    triangle fits the manifold mesh. A longer loop (up to 400 edges), or a short one that
 *    triangulation could not close, is closed when it is narrow: by the triangulation of its own
 *    vertices of least largest dihedral angle (pcs::holes::LeastDihedralFill, after Liepa, SGP
 *    2003, section 3.1), kept only when the centroid and the midpoints of the new edges of every
 *    triangle lie within 2 local spacings of an input point (among the loop's vertices and their K
 *    nearest neighbours) -- the Hausdorff bound asked of the whole mesh. The local spacing is the
 *    mean distance of the loop's vertices to their nearest neighbours, or the cloud's mean spacing
 *    when larger: on a densely and anisotropically sampled thin feature (the camel's ears: nearest
 *    neighbours 0.26 mean spacings away, mesh edges 0.7-0.9) the local value alone refused fills
 *    within 0.8 mean spacings of the points. A loop whose vector area exceeds 4 local spacings
 *    times its perimeter cannot pass and is not triangulated (the fill is cubic in the loop's
 *    length). Constraint 1 is not asked of this fill: on CGAL's mesh vertex sets every loop the
 *    growth leaves lies on a thin or sharply bent feature (ear and lip rims, the camel's tail and
 *    legs, the armadillo's ear) and its least-dihedral fill bends by 105 to 175 degrees somewhere.
 *    What tells a sampling gap from a membrane between parts that only come close (the camel's
 *    legs: fill points up to 3 mean spacings from every point) is whether the fill stays near the
 *    points. Measured with the default parameters (boundary edges before -> after): camel vertices
 *    319 -> 80 (1.1 -> 0.27 %; CGAL's advancing front 94), diplodocus 54 -> 0, armadillo 12 -> 0,
 *    elephant 30 -> 0 (the three closed, genus 1, 1 and 3; the elephant's is its mesh's), 10^5
 *    samples of the camel 264 -> 95, of the elephant 24 -> 0 (closed, genus 3), of the armadillo 29
 *    -> 20; random tori not closed over every point 1 of 120 -> 0; Hausdorff distances unchanged
 *    (Benchmarks/results/local_optimum.md). Filling a loop never changes the genus: the handles
 *    are made by bridges during the growth (step 4; the armadillo and the diplodocus are genus 0
 *    now, the camel keeps one handle of three, its loops open or closed). Neither fill may fold
 *    back onto the mesh: a fill triangle in the plane of the mesh triangle across a loop edge
 *    (exact Orient3D) and on the same side of that edge (exact Orient2D) overlaps it. The border
 *    of a small flat patch (30 to 200 points of a planar scan, a box's face) was filled that
 *    way into a second layer back to back with the patch, a closed component enclosing no
 *    volume, and CAD vertex sets kept such layers on their flat faces (turbine: 213 edges with
 *    both triangles on one side, 13 now; its boundary edges 635 -> 835, Hausdorff unchanged). A
 *    narrow-loop fill is refused at the first such edge; a small-loop fill only when it folds at
 *    every loop edge it shares a plane with (a hole beside a fold of the growth itself, one edge
 *    of six on a sphere sampled on latitude circles, is still closed). Both fills must also be a
 *    small part of the surface they complete: the mesh triangles reached from the loop's edges
 *    have more than twice the fill's area (pcs::holes::FillIsSmallPartOfSurface). This tells the
 *    fill of a true hole, a gap in a surface, from a lid or a pillow: the border of an open patch
 *    can only be "closed" by a fill about as large as the patch -- a lid over a bowl, or a second
 *    layer back to back with a flat or tilted patch that is not exactly coplanar (which the fold
 *    rule does not see). Small bowls and saddles of 20 to 2,000 random or grid points came back
 *    closed 31 times of 70 before, tilted discs of 20 to 200 random points 13 times of 25; none
 *    after: one component with one boundary loop.
 *    Where a fill is refused by this rule the piece stays open: the small separate pieces that
 *    step 5 does not take apart, which such fills had closed into pillows beside the surface,
 *    are counted by the boundary-edge figures now (Benchmarks/results/local_optimum.md, "Lids
 *    and pillows").
 * 7. Folds (added): an edge whose two triangles bend by more than MaximumNormalAngle (the
 *    bound of constraint 1) is flipped when the other diagonal of its quadrilateral is not in the
 *    mesh and is shorter, or joins two K nearest neighbours (one is among the other's: an edge
 *    the growth could have made), and the flip raises the smallest normal dot product among the
 *    five edges of the quadrilateral (the edge and the four around it); the mesh checks the two
 *    new triangles (oriented, manifold) before they are kept, and the edges around a flipped edge
 *    are tried again (at most 4 flips per triangle on average). On noisy scans the folds are small
 *    standing triangles (three points nearly in line in the tangent plane at different noise
 *    heights) whose unfolding diagonal is often the longer one. A longer diagonal beyond the K
 *    nearest, across a sparse, sharply bent spot, leaves the surface: allowed, it made the 10^5
 *    armadillo samples' Hausdorff 1.79 -> 2.12 mean spacings. Measured (edges bending by more than
 *    90 degrees, shorter diagonal only -> with K-neighbour diagonals; Benchmarks/results/
 *    local_optimum.md): random spheres of 20,000 points with Gaussian noise of 0.1 and 0.2
 *    sqrt(area / N) 1012 -> 644 and 3050 -> 2599 (CGAL's advancing front 264 at 0.1), CGAL's
 *    bunny00 vertices with noise of 0.25 mean spacings 4708 -> 4339, clean 10^5 mesh samples
 *    73-370 -> 41-212, with every Hausdorff distance, boundary edge count and coverage unchanged.
 *    (Also asking the four points to lie within the noise band of their plane, the rule of
 *    vtkCDTAdvancingFront::NoiseBandFactor, changed nothing once the diagonal is a K-neighbour
 *    pair: not kept.) Of the 644 folds left on that sphere, 223 have their other diagonal in the
 *    mesh already (mostly at a vertex of 3 triangles) and 396 would not be less folded by the
 *    flip; the triangles standing up against the surface there were made at the last relaxation
 *    level (40 %: a point close to an edge admitted by its height), at the others, by orphan
 *    insertions and by hole fills (temporary trace). On clean clouds such folds are left where
 *    ears, later-stage expansions and hole fills meet at a sharply bent spot (on 10^5 samples of
 *    CGAL's armadillo 1015 edges bend by more than 90 degrees, 368 with the shorter diagonal,
 *    212 now): the worst triangle of that cloud, folded by 139 degrees against a hole fill, set
 *    its Hausdorff distance (2.07 mean spacings, 1.79 after), and on the elephant samples a
 *    corner cut by the wrong diagonal set it (2.13, 1.66 after). Flips of edges bending by more
 *    than 90 degrees only (instead of MaximumNormalAngle) gave 1.94 and 2.13. Slivers (angles
 *    below 1 degree) left by step 5 may still fold, and so may a triangle folded against all three
 *    of its neighbours, which no single flip improves (two of the five hard random torus samples
 *    of the test keep one).
 *    Long edges across thin tips (second pass, added): an edge longer than 3 local spacings (the
 *    mean, over the four vertices of its quadrilateral, of their mean distance to their 6 nearest
 *    neighbours) whose other diagonal is absent from the mesh and shorter than 0.8 times the edge
 *    is flipped when the flip folds nothing (the smallest normal dot product among the five edges
 *    of the quadrilateral stays at least min(before, cos MaximumNormalAngle)), or when it brings
 *    the two triangles nearer to the points (the largest distance from their centroids and the
 *    diagonal's midpoint to the nearest input point among the four vertices and their K nearest
 *    falls by the factor 0.8) without folding over (normals more than 90 degrees apart) a
 *    quadrilateral that was not folded over, and without making the thinner triangle less than a
 *    quarter as fat as before (twice its area over its longest edge squared: no sliver along a
 *    scan line, which lies on the points but stands across the surface). On random samples such an
 * edge joins the two sides of a thin, sharply bent tip (a tusk, a claw) and its triangles cut
 * across the inside, 2-3 mean spacings off the surface. Measured (Benchmarks/run_sample_seeds.py,
 * 20 random 10^5 samples of CGAL's camel, elephant, armadillo and bunny00, seeds 1-5;
 * Benchmarks/results/ local_optimum.md): Hausdorff distance within 2 mean spacings on 10 -> 12 of
 * them (elephant seed 2 2.22 -> 1.42, armadillo seed 5 2.03 -> 1.74), none worse by more than 0.01,
 * boundary edges and coverage unchanged; CGAL's held-out mesh vertex sets
 * (run_mesh_vertex_sweep.py): boundary edges unchanged, Hausdorff distances equal or lower
 * (ChineseDragon-10kv 1.53 -> 1.32, femur 1.75 -> 1.68). The walls across thin tubes (discs across
 * a leg or a tail of radius 2-3 spacings) are not quadrilaterals with a wrong diagonal and stay.
 * 8. Each closed component is oriented outwards (positive signed volume).
 *
 * Output: all input points and point data, the triangles (consistently oriented), point data
 * `Used` (1 for a vertex of a triangle, else 0) and `RepresentativeId` (the point that
 * represents each input point: itself, the first of a group of duplicates -- exact copies or a
 * pile, see below --, or -1 for a point with a NaN or infinite coordinate); field data
 * `NumberOfInputPoints`, `NumberOfTriangles`, `NumberOfSeeds`, `NumberOfHolesClosed`,
 * `NumberOfUnusedPoints` (distinct finite points no triangle uses, outliers included; not the
 * duplicates), `NumberOfDuplicatePoints` (exact and near copies, see below),
 * `NumberOfSkippedPoints` (non-finite), `NumberOfBoundaryEdges` (edges of a single triangle left in
 * the mesh), `NumberOfOutliers` (far outliers excluded, OutlierFactor).
 *
 * Cost: O(KN) for N points (the paper's bound): the neighbour search is done once, each front
 * edge examines at most 2K candidates and their neighbourhood, and every topological query is
 * O(1). Memory: about 4K + 230 bytes per point (32 of them for the bin grid). The neighbour
 * search is threaded (vtkSMPTools); the growth is sequential.
 *
 * @warning
 * The method assumes a surface sampled densely enough that K neighbours reach across every
 * triangle to be made (noise-free or lightly noisy scans; uniform or moderately non-uniform
 * density). Features sharper than MaximumNormalAngle cannot be crossed by one triangle, and sharp
 * creases are often not crossed at all: the rim of a closed cone (faces 135 degrees apart) and
 * the edges of a box 2.5 spacings thick are left open (boundary loops along them; diagnosis in
 * Benchmarks/results/local_optimum.md, task logsharp). Sheets closer than about 2.8 mean
 * spacings may be joined into one surface (concentric spheres 2 spacings apart always are). Points
 * that no valid triangle reaches (outliers, isolated points, thin features) are left unused and
 * reported. Duplicate points are meshed once, the first of their group along the Hilbert curve
 * (the others have Used = 0, RepresentativeId that point, and are counted in
 * NumberOfDuplicatePoints, with a warning): exact copies, and the points of a pile of
 * near-coincident points (a scanner's repeated returns at one spot, jittered copies; ours,
 * beyond the paper), as in vtkCDTAdvancingFront: a group whose extent is under 1/10,000 of its
 * distance to the rest of the cloud, found on the first 8 columns of the K-neighbour table
 * (pcs::FindPiles, the definition vtkCDTAdvancingFront's duplicates and the far-outlier rule
 * share; with NumberOfNeighbors under 8, on a table of 8 searched for it). The tolerance is
 * relative to the sampling around the group, no absolute or global distance. A pile meshed point
 * by point made a blob of needle triangles: 1,000 sphere points and 4 piles of 600 gave 5,358
 * triangles, 3,363 of them with an edge under 1e-5 of the radius, and 716 boundary edges (now
 * 1,996, 2V - 4, closed; Benchmarks/results/robustness.md, "Piles are duplicates in LOG, greedy
 * and the peel"). Fewer than 3 distinct finite points, or collinear clouds, give a warning and
 * an output without triangles. On random samples the mesh is farthest from the sampled surface at
 * thin, sharply bent tips (ears, claws), where the nearest sample lies a few mean spacings from
 * the tip: measured on 10^5 samples of CGAL's camel, the worst reference vertex is 2.36 mean
 * spacings from our mesh and from CGAL's advancing-front mesh alike, and 2.38 from the convex
 * hull of its 30 nearest samples, so that no mesh over these points comes within 2 spacings of
 * it. Thin tubes sampled by sparse rings (edge ratios above 3, as in decimated meshes) are left
 * with holes; the open end of a tube whose radius is below about 2 spacings is capped (step 6:
 * it cannot be told from a sampling gap). Random closed samples are closed over every point on
 * most seeds, not all (see step 4).
 *
 * @sa
 * vtkCDTAdvancingFront vtkGreedySurfaceTriangulation vtkReconstructionQuality
 * vtkStaticPointLocator
 */

#ifndef vtkLocalOptimumGrowth_h
#define vtkLocalOptimumGrowth_h

#include "vtkPointCloudSurfaceFiltersModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

class vtkStaticPointLocator;

class VTKPOINTCLOUDSURFACEFILTERS_EXPORT vtkLocalOptimumGrowth : public vtkPolyDataAlgorithm
{
public:
  static vtkLocalOptimumGrowth* New();
  vtkTypeMacro(vtkLocalOptimumGrowth, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Number K of nearest neighbours of each point among which the triangles are made. Default
   * 20; range [4, 200]. Larger values reach across sparser regions at a linear cost.
   */
  vtkSetClampMacro(NumberOfNeighbors, int, 4, 200);
  vtkGetMacro(NumberOfNeighbors, int);
  ///@}

  ///@{
  /**
   * Constraint 1: largest angle, in degrees, between the normal of a new triangle and the
   * normal of the triangle across the expanded edge. Default 60 (the paper's pi/3); range
   * [1, 179].
   */
  vtkSetClampMacro(MaximumNormalAngle, double, 1.0, 179.0);
  vtkGetMacro(MaximumNormalAngle, double);
  ///@}

  ///@{
  /**
   * Constraint 2: the lengths |ac| and |bc| of the new edges must lie in [MinimumEdgeRatio d,
   * MaximumEdgeRatio d], d = |ab| the expanded edge. Defaults 1/3 and 3 (the paper's k1, k2);
   * ranges [0, 1] and [1, 1000].
   */
  vtkSetClampMacro(MinimumEdgeRatio, double, 0.0, 1.0);
  vtkGetMacro(MinimumEdgeRatio, double);
  vtkSetClampMacro(MaximumEdgeRatio, double, 1.0, 1000.0);
  vtkGetMacro(MaximumEdgeRatio, double);
  ///@}

  ///@{
  /**
   * Constraint 3: largest angle, in degrees, of a new triangle at either end of the expanded
   * edge; 90 keeps the projection of the new point on the edge (the paper's rule, which leaves
   * many front edges of random samplings without a candidate). Default 120; range [30, 179].
   */
  vtkSetClampMacro(MaximumBaseAngle, double, 30.0, 179.0);
  vtkGetMacro(MaximumBaseAngle, double);
  ///@}

  ///@{
  /**
   * Boundary loops of at most this many edges are closed at the end (0 closes none); longer
   * loops only when narrow (their fill stays within 2 local spacings of the points, step 6).
   * Default 8; range [0, 1000].
   */
  vtkSetClampMacro(MaximumHoleEdges, int, 0, 1000);
  vtkGetMacro(MaximumHoleEdges, int);
  ///@}

  ///@{
  /**
   * Grow first with flat candidates only (bending by at most half of MaximumNormalAngle); when
   * the front stalls, retry the edges set aside with every candidate, then with constraint 2
   * relaxed (first [k1/2, 2 k2], then no lower bound) before planting a new seed. Default on;
   * off applies the paper's constraints strictly.
   */
  vtkSetMacro(RelaxConstraints, bool);
  vtkGetMacro(RelaxConstraints, bool);
  vtkBooleanMacro(RelaxConstraints, bool);
  ///@}

  ///@{
  /**
   * Far outliers are excluded before the neighbour search and reported (point data Used = 0,
   * field data NumberOfOutliers, a warning; counted in NumberOfUnusedPoints too): the rule of
   * vtkPerimeterPeelSurface::OutlierFactor (pcs::FindOutliersAndPiles), same meaning: a point whose
   * reach (mean distance to its 8 nearest points) is over 4 times the cloud's median reach and
   * over OutlierFactor times the median reach of its 8 nearest points that are not, unless it
   * lies on a sparse part of the surface (its 8 nearest sparse too and flat around it: see the
   * peel's docs). A pile of near-coincident points (pcs::FindPiles) counts as one point with
   * one verdict (see the peel's docs); a pile that is not an outlier is meshed once (its other
   * points are duplicates, see the class docs). Default 8.0;
   * range [0, 1000]; 0: off. With NumberOfNeighbors >= 8 the rule and the piles read the first 8
   * columns of the K-neighbour table (no search of their own; the table is searched again
   * without the outliers and the piles' duplicates when there are any); with fewer, one search
   * of 8 neighbours for both (pcs::RemoveOutliersAndPiles; also when OutlierFactor is 0).
   */
  vtkSetClampMacro(OutlierFactor, double, 0.0, 1000.0);
  vtkGetMacro(OutlierFactor, double);
  ///@}

  ///@{
  /**
   * Denoising of the geometry (ours, step 1): the triangles are chosen on a copy of the points
   * each projected onto the least-squares plane of itself and its 19 nearest neighbours
   * (pcs::ProjectOntoLocalPlanes), the output keeps the input points. Off (0): never;
   * On (1): always; Automatic (2, the default): when the cloud is noisy
   * (pcs::MeasureSamplingNoise: the median height noise of quadric fits is more than 1/20 of the
   * median local spacing and more than the median plane residual). Range [0, 2]. See "Noise"
   * in the class docs.
   */
  vtkSetClampMacro(LocalPlaneProjection, int, 0, 2);
  vtkGetMacro(LocalPlaneProjection, int);
  void SetLocalPlaneProjectionToOff() { this->SetLocalPlaneProjection(0); }
  void SetLocalPlaneProjectionToOn() { this->SetLocalPlaneProjection(1); }
  void SetLocalPlaneProjectionToAutomatic() { this->SetLocalPlaneProjection(2); }
  ///@}

  ///@{
  /**
   * The point locator used for the K-nearest-neighbour search. Default none: the search files
   * the points into its own grid of about 4 bins per point (pcs::PointBins), which the scan-line
   * search (step 1) reuses; no vtkStaticPointLocator is built. A locator set here is built and
   * used by both, with its own bin settings.
   */
  void SetLocator(vtkStaticPointLocator* locator);
  vtkGetObjectMacro(Locator, vtkStaticPointLocator);
  ///@}

  ///@{
  /**
   * Counts from the last execution (also in the output's field data).
   */
  vtkGetMacro(NumberOfInputPoints, vtkIdType);
  vtkGetMacro(NumberOfTriangles, vtkIdType);
  vtkGetMacro(NumberOfSeeds, vtkIdType);
  vtkGetMacro(NumberOfHolesClosed, vtkIdType);
  vtkGetMacro(NumberOfUnusedPoints, vtkIdType);
  vtkGetMacro(NumberOfDuplicatePoints, vtkIdType);
  vtkGetMacro(NumberOfSkippedPoints, vtkIdType);
  vtkGetMacro(NumberOfBoundaryEdges, vtkIdType);
  vtkGetMacro(NumberOfOutliers, vtkIdType);
  /// Whether the triangles were chosen on the projected points (LocalPlaneProjection), and the
  /// noise measures of pcs::MeasureSamplingNoise (0 when LocalPlaneProjection is not
  /// automatic; those of its first sample of 500 points when that settled the decision).
  vtkGetMacro(ProjectedOntoLocalPlanes, bool);
  vtkGetMacro(NoiseLevel, double);
  vtkGetMacro(NoiseShare, double);
  ///@}

  vtkMTimeType GetMTime() override;

protected:
  vtkLocalOptimumGrowth();
  ~vtkLocalOptimumGrowth() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int NumberOfNeighbors = 20;
  // The constraints: set by the constructor from pcs::FrontGrowthParameters' defaults.
  double MaximumNormalAngle;
  double MinimumEdgeRatio;
  double MaximumEdgeRatio;
  double MaximumBaseAngle;
  int MaximumHoleEdges;
  bool RelaxConstraints;
  double OutlierFactor = 8.0;
  int LocalPlaneProjection = 2; // automatic
  vtkStaticPointLocator* Locator = nullptr;

  vtkIdType NumberOfInputPoints = 0;
  vtkIdType NumberOfTriangles = 0;
  vtkIdType NumberOfSeeds = 0;
  vtkIdType NumberOfHolesClosed = 0;
  vtkIdType NumberOfUnusedPoints = 0;
  vtkIdType NumberOfDuplicatePoints = 0;
  vtkIdType NumberOfSkippedPoints = 0;
  vtkIdType NumberOfBoundaryEdges = 0;
  vtkIdType NumberOfOutliers = 0;
  bool ProjectedOntoLocalPlanes = false;
  double NoiseLevel = 0.0;
  double NoiseShare = 0.0;

private:
  vtkLocalOptimumGrowth(const vtkLocalOptimumGrowth&) = delete;
  void operator=(const vtkLocalOptimumGrowth&) = delete;
};

#endif
