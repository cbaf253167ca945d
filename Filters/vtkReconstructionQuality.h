/**
 * @class   vtkReconstructionQuality
 * @brief   topological and geometric quality measures of a reconstructed triangle mesh,
 *          optionally against a reference surface or the original point cloud.
 *
 * vtkReconstructionQuality analyses the triangles of a vtkPolyData (input port 0) -- typically
 * the output of a surface reconstruction filter, whose points may include cloud points that no
 * triangle uses -- and, when a reference is connected to input port 1, the distance between the
 * mesh and that reference. The output is a shallow copy of the input mesh with the measures
 * added as cell, point and field data; the input is never modified.
 *
 * Definitions. The analysed triangles are the polygons with exactly 3 point ids. A triangle
 * whose ids are not distinct ("collapsed") is counted as degenerate and takes no part in the
 * topology; every other triangle, including zero-area and duplicate triangles, does. An edge is
 * an unordered pair of point ids; its valence is the number of triangles that have it.
 * Point data:
 * - `Used`: 1 when the point is a vertex of a triangle (collapsed ones included), else 0.
 * - `NonManifoldVertex`: 1 when the triangles around the point do not form a single fan -- the
 *   triangles incident to the point, linked when they share an edge at the point, form more than
 *   one connected component -- or when the point is on a non-manifold edge; else 0.
 * - `DistanceToReference` (with a reference, ComputeDistances on): unsigned distance from the
 *   point to the reference (see below); NaN for unused points.
 * Cell data (one value per cell of the mesh; -1 or NaN for cells that are not analysed:
 * vertices, lines, strips, polygons with another point count, collapsed triangles for the edge
 * counts):
 * - `NonManifoldEdge`: number of the triangle's edges of valence > 2 (0 to 3).
 * - `BoundaryEdge`: number of the triangle's edges of valence 1 (0 to 3).
 * - `MinAngle`: smallest interior angle of the triangle in degrees (0 for degenerate ones).
 * Field data (one tuple each):
 * - `NumberOfTriangles` (3-point polygons), `NumberOfUsedPoints`, `Coverage` (used points /
 *   input points, 0 without points).
 * - `NumberOfNonManifoldEdges` (valence > 2), `NumberOfNonManifoldVertices`,
 *   `NumberOfBoundaryEdges` (valence 1).
 * - `NumberOfBoundaryLoops`: closed loops of boundary edges. A loop is walked from a boundary
 *   edge: at its end point the next boundary edge is found by turning around the point through
 *   the fan of triangles linked by valence-2 edges, whatever the triangle orientation. The loops
 *   are thus those of the surface obtained by splitting every non-manifold point into one copy
 *   per fan: two disks touching at a point have 2 loops, two holes of one sheet touching at a
 *   corner form 1 loop. A walk that meets a non-manifold edge is an open chain, not counted.
 * - `NumberOfConnectedComponents`: components of the triangles linked through shared edges
 *   (triangles touching only at a vertex are in different components).
 * - `EulerCharacteristic`: V - E + F of the non-collapsed triangles (V: their distinct vertices,
 *   E: their distinct edges, F: their number, duplicates included).
 * - `Genus`: when the mesh is closed (no boundary edge), manifold (no non-manifold edge or
 *   vertex) and every component is orientable, the sum of the genera of its components,
 *   (2 C - EulerCharacteristic) / 2 with C components (for one component the usual
 *   (2 - chi) / 2); otherwise -1.
 * - `OrientationConsistency`: fraction of the valence-2 edges whose two triangles traverse the
 *   edge in opposite directions (1 when the mesh has no valence-2 edge).
 * - `NumberOfDegenerateTriangles`: triangles with a repeated point id or zero area (decided
 *   exactly at any scale: the three points are collinear, by exact orientation predicates on
 *   the points scaled by a power of two when their coordinates are tiny or huge).
 * - `NumberOfDuplicateTriangles`: triangles with the same point-id set as an earlier triangle
 *   (a pair counts 1).
 * - `MinAngleP1`: 1st percentile (nearest rank) of the per-triangle MinAngle (NaN without
 *   triangles).
 *
 * Distances (input port 1 connected and ComputeDistances on). The reference is a surface when it
 * has triangle cells (VTK_TRIANGLE or 3-point polygons), otherwise a cloud (all its points).
 * Points with a NaN or infinite coordinate are left out on both sides (with their triangles),
 * with a warning. Each side is sampled deterministically: its vertices (for the mesh its used
 * points, for a reference surface the points of its triangles, for a cloud all its points) plus
 * SamplesPerTriangle points in every triangle, the first the centroid, the others the R2
 * low-discrepancy sequence (Roberts, 2018) folded into the triangle. The distance from a sample
 * to a surface is the distance to the closest of its triangles of non-zero area, as
 * vtkTriangle::EvaluatePosition computes it (the value vtkStaticCellLocator::FindClosestPoint
 * gives); to a cloud, or to a surface without such triangles, the distance to the nearest point.
 * Both are exact minima found by one search for all the samples: the samples are split
 * recursively into halves (a k-d tree on the samples) and each node keeps the triangles (points)
 * that can be the closest to one of its samples, bounded through the distances to the triangle
 * closest to the node's centre and tested by three lower bounds (the gap between the boxes, the
 * distance from the centre minus the node's half-diagonal, the gaps along the triangle's normal
 * and edge normals). On slivers (twice the area below 1e-5 times the longest edge squared), where
 * a distance computed from the region of the point is unreliable, only the bounds that hold for
 * any shape prune them (boxes, the slab of the triangle's points along its computed normal),
 * checked against a brute-force exact distance on soups of slivers down to 1e-14 relative
 * thickness, needles and long triangles (TestReconstructionQualityBruteForce). Unlike a grid or a tree of triangle boxes, where a long triangle sits in
 * every bin its box touches, this stays near-linear for meshes of long thin triangles (a fan of
 * slivers, a triangle soup over a cloud: 2 x 10^4 triangles against a sphere took 44 to 74 s
 * with vtkStaticCellLocator, 1.4 to 1.9 s now, same values). Coordinates beyond [2^-60, 2^60] in
 * magnitude (1e300, 1e-300) are scaled by a power of two for the distances, the spacing, the
 * zero-area test and the angles (exact, so the values are those of the unscaled computation);
 * samples whose distance cannot be computed (overflow) are NaN, with a warning, as are
 * triangles too thin for EvaluatePosition at their coordinate range (left out, with a warning).
 * - `AccuracyMean`, `AccuracyMax`: mean and maximum over the mesh samples of the distance to the
 *   reference (unweighted mean: every triangle gets the same number of samples).
 * - `CompletenessMean`, `CompletenessMax`: the same from the reference samples to the mesh.
 * - `Hausdorff`: max(AccuracyMax, CompletenessMax), the sampled symmetric Hausdorff distance.
 * - `MeanSpacing`: mean nearest-neighbour distance of the cloud: the mesh's used points when the
 *   reference is a surface, the reference's points when it is a cloud (exact duplicates are
 *   skipped when looking for the nearest neighbour; the copies of a point share one query, so
 *   a pile of copies costs about its size, not its square).
 * - `AccuracyMeanOverSpacing`, `AccuracyMaxOverSpacing`, `CompletenessMeanOverSpacing`,
 *   `CompletenessMaxOverSpacing`, `HausdorffOverSpacing`: the distances divided by MeanSpacing
 *   (NaN when the spacing is 0 or undefined).
 * When one side is empty the distances are NaN (with a warning).
 *
 * Reference normal angles (a reference surface connected, ComputeDistances on). They show
 * triangles standing across the surface -- slivers of tiny area that the distances do not see
 * but shading and curvature do.
 * - `ReferenceNormalAngle` (cell data): the angle in degrees, 0 to 90, between the triangle's
 *   normal and the normal of the reference triangle closest to the triangle's centroid (found by
 *   the accuracy search above: the centroid is the first sample of every triangle; with
 *   SamplesPerTriangle 0 the centroids are queried as well and left out of the accuracy).
 *   Unoriented (the acute angle, atan2(|m x n|, |m . n|)), since the reference's orientation may
 *   differ from the mesh's or be missing. Normals come from the two shorter edges of the
 *   triangle (on coordinates scaled as for the distances). NaN for degenerate triangles (repeated
 *   id or zero area), cells that are not analysed, and when the reference is a cloud.
 * - `MeanReferenceNormalAngle`: the unweighted mean over the triangles with an angle: every
 *   triangle counts once, so slivers standing across the surface raise it however small they
 *   are. `AreaWeightedMeanReferenceNormalAngle`: the mean weighted by triangle area: the share of
 *   the surface's area that is tilted, as the shading of large faces shows it. NaN with a
 *   reference cloud or without such triangles.
 * - `NumberOfStandingTriangles`: triangles whose angle is above StandingAngle; -1 with a
 *   reference cloud.
 *
 * Cost: the topology is O(T log T) for T triangles (one sort of the 3T half-edges), the fans
 * O(sum of point degrees); peak memory about 250 bytes per triangle. The distances cost about
 * (samples + triangles near them) x log(samples); memory about 40 bytes per sample and 260 per
 * target triangle (point), plus the triangle lists of the 64 top subtrees of the search. Samples
 * inside a closed reference far from its surface (the samples of triangles crossing it) have
 * many nearly equidistant targets, which no box bound separates: there the cost grows faster
 * (about T^1.4 for a triangle soup inside a sphere sampled by a cloud). The fans and the
 * distance queries run in parallel with vtkSMPTools::For (the top subtrees of the search are
 * the tasks, each thread with its own vtkTriangle). The per-sample distances are stored and
 * reduced in sample order, so the results do not depend on the SMP backend or the thread count
 * (tested: Sequential and STDThread agree bit for bit).
 *
 * @warning
 * Polygons with more or fewer than 3 points and triangle strips are ignored (not triangulated),
 * with a warning; vertex and line cells are ignored silently. Triangles with out-of-range point
 * ids are ignored with a warning. An input without points or without triangles gives a warning
 * and a valid output with zero counts. Under MPI the mesh and the reference are gathered on
 * process 0, which measures them whole (the serial result); the other processes' outputs are empty.
 *
 * @sa
 * vtkIncrementalDelaunay3D vtkMeshQuality vtkFeatureEdges vtkDistancePolyDataFilter
 * vtkStaticCellLocator vtkTriangle
 */

#ifndef vtkReconstructionQuality_h
#define vtkReconstructionQuality_h

#include "vtkPointCloudSurfaceFiltersModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

class vtkAlgorithmOutput;
class vtkDataObject;

class VTKPOINTCLOUDSURFACEFILTERS_EXPORT vtkReconstructionQuality : public vtkPolyDataAlgorithm
{
public:
  static vtkReconstructionQuality* New();
  vtkTypeMacro(vtkReconstructionQuality, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The optional reference (input port 1): a vtkPointSet that is either a surface (its triangle
   * cells are used) or a point cloud (no triangle cells: its points are used). Equivalent to
   * SetInputConnection(1, output) / SetInputData(1, data); nullptr disconnects it.
   */
  void SetReferenceConnection(vtkAlgorithmOutput* output);
  void SetReferenceData(vtkDataObject* data);
  ///@}

  ///@{
  /**
   * Number of sample points per triangle, besides the vertices, for the accuracy and
   * completeness distances (the first is the centroid, the others follow the R2 sequence).
   * Default 3; range [0, 100]. 0 samples the vertices only.
   */
  vtkSetClampMacro(SamplesPerTriangle, int, 0, 100);
  vtkGetMacro(SamplesPerTriangle, int);
  ///@}

  ///@{
  /**
   * Compute the distances to the reference (point data DistanceToReference, field data
   * Accuracy*, Completeness*, Hausdorff*, MeanSpacing) and, with a reference surface, the
   * reference normal angles. Default on. Only matters when a reference is connected to input
   * port 1.
   */
  vtkSetMacro(ComputeDistances, bool);
  vtkGetMacro(ComputeDistances, bool);
  vtkBooleanMacro(ComputeDistances, bool);
  ///@}

  ///@{
  /**
   * A triangle whose ReferenceNormalAngle is above this angle (degrees) counts in
   * NumberOfStandingTriangles: it stands across the reference surface rather than along it.
   * Default 60; range [0, 90]. Only matters with a reference surface and ComputeDistances on.
   */
  vtkSetClampMacro(StandingAngle, double, 0.0, 90.0);
  vtkGetMacro(StandingAngle, double);
  ///@}

protected:
  vtkReconstructionQuality();
  ~vtkReconstructionQuality() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int SamplesPerTriangle = 3;
  bool ComputeDistances = true;
  double StandingAngle = 60.0;

private:
  vtkReconstructionQuality(const vtkReconstructionQuality&) = delete;
  void operator=(const vtkReconstructionQuality&) = delete;
};

#endif
