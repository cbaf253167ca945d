/**
 * @class   vtkIncrementalDelaunay3D
 * @brief   exact incremental Delaunay tetrahedralization (and 2.5D triangulation)
 *          of a point set, with its convex hull and Voronoi diagram.
 *
 * vtkIncrementalDelaunay3D computes the Delaunay tetrahedralization of the points of any
 * vtkPointSet (cells of the input are ignored). It is the kernel every surface filter of
 * PointCloudSurface stands on.
 *
 * Algorithm (paper 000, Rodriguez et al., DGCI 2000, section 2; paper 002, Cocias et al.,
 * section 3.1): randomized incremental construction. Points are inserted in a spatially
 * coherent order (biased randomized insertion order, BRIO, with a Hilbert curve order inside
 * each round -- the "Incremental constructions con BRIO" reference of paper 002). Each point is
 * located by a visibility walk that starts from the last created tetrahedron; the tetrahedra
 * whose circumsphere contains it (the Bowyer-Watson cavity of paper 000, section 2, steps 2-6)
 * are removed and the cavity is re-tetrahedralized as a star around the new point. Unlike paper
 * 000, there is no bounding cube: the triangulation is closed by a symbolic "infinite" vertex,
 * so the result is the exact Delaunay tetrahedralization of the input, with its complete convex
 * hull and no artefact of a finite box. Cells are stored in flat arrays (4 vertices + 4
 * neighbours each) without per-insertion allocation.
 *
 * Robustness: every orientation and insphere decision uses exact predicates (a floating-point
 * filter with a proven error bound -- Shewchuk's stage-A bounds, preceded by a cheaper
 * semi-static bound for insphere -- falling back to exact expansion arithmetic). Cospherical
 * and coplanar configurations are resolved by symbolic perturbation of the lifted coordinate
 * of each point (ranked lexicographically by coordinates), so the output does not depend on the
 * insertion order and no point is ever dropped. Exact duplicate points are merged (the output
 * keeps every input point id; the point data array `RepresentativeId` names the input point that
 * represents each point in the triangulation, and a warning states the count). A positive
 * Tolerance also merges points closer than Tolerance. Points with NaN or infinite coordinates
 * are skipped and counted (their `RepresentativeId` is -1). Coordinates beyond 2^60 or below
 * 2^-60 in magnitude are scaled internally by a power of two (an exact operation) so that the
 * exact arithmetic never overflows or underflows; all outputs are in the input's units.
 *
 * 2.5D mode (paper 002, sections 2.2 and 3.1): with Dimension = 2 the points are projected onto
 * the x-y plane (or their least-squares plane, see ProjectionPlane), triangulated by
 * incremental insertion with Lawson edge flips under exact orient2d / incircle predicates, and
 * the triangles are lifted back to the 3D points: output 0 is then the terrain-like triangle
 * mesh. Points whose projections coincide are merged as duplicates.
 *
 * Outputs:
 * - port 0 (vtkPolyData): in 3D the boundary triangles of the tetrahedralization (the convex
 *   hull, oriented outwards); in 2.5D the lifted triangulation. ALL input points and their point
 *   data are passed through, plus point data `RepresentativeId`; field data
 *   `NumberOfInputPoints`, `NumberOfDuplicatePoints`, `NumberOfSkippedPoints` (non-finite),
 *   `NumberOfTetrahedra` (or triangles in 2.5D).
 * - port 1 (vtkUnstructuredGrid): the tetrahedra (triangles in 2.5D) over the same points,
 *   positively oriented, with cell data `Circumradius`. Produced when GenerateTetrahedra is on.
 * - port 2 (vtkPolyData): the Voronoi diagram, dual of the triangulation (paper 002, section
 *   2.1): one vertex per Delaunay cell (its circumcentre, point data `Circumradius`; for a flat
 *   cell -- four cocircular points, e.g. of one scan ring -- the centre of their circle), one line
 *   per pair of adjacent cells (a Voronoi edge, dual of a Delaunay facet), and for every hull
 *   facet a ray, clipped at one bounding-box diagonal from its circumcentre and marked by the
 *   cell data `Unbounded` = 1. Produced when GenerateVoronoi is on.
 *
 * Cost: O(n log n) expected time for well-distributed points; about 6.7 tetrahedra per point
 * in 3D, held by the kernel in 32-byte records (vertices and neighbour links side by side), so
 * about 220 bytes per point during the construction, then the VTK output arrays. Exact
 * duplicates are detected during point location at no extra cost. With VTK's STDThread (or TBB)
 * SMP backend the spatial sort and the output stage use all cores; the insertion is sequential.
 * Some point sets have a much larger tetrahedralization: points along a curve (a helix: about
 * n^1.5 tetrahedra; the moment curve: n^2 / 2) or arranged on a cylinder (Erickson, "Nice point
 * sets can have nasty Delaunay triangulations"); the filter then warns (more than 25 tetrahedra
 * per distinct point), since time and memory grow with the tetrahedra.
 *
 * @warning
 * In 3D at least 4 non-coplanar points are needed; with fewer (or when all points are coplanar)
 * the filter warns and outputs the points without cells. In 2.5D at least 3 non-collinear
 * projected points are needed. The Voronoi diagram of a large cloud is about three times the
 * size of its tetrahedralization: it is off by default.
 *
 * @sa
 * vtkDelaunay3D vtkDelaunay2D vtkPerimeterPeelSurface
 */

#ifndef vtkIncrementalDelaunay3D_h
#define vtkIncrementalDelaunay3D_h

#include "vtkPointCloudSurfaceFiltersModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

class vtkPointSet;
class vtkPolyData;
class vtkUnstructuredGrid;

class VTKPOINTCLOUDSURFACEFILTERS_EXPORT vtkIncrementalDelaunay3D : public vtkPolyDataAlgorithm
{
public:
  static vtkIncrementalDelaunay3D* New();
  vtkTypeMacro(vtkIncrementalDelaunay3D, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum ProjectionPlanes
  {
    XY_PLANE = 0,
    BEST_FIT_PLANE = 1
  };

  ///@{
  /**
   * Dimension of the triangulation: 3 (default) computes the Delaunay tetrahedralization;
   * 2 computes the 2.5D (lifted) Delaunay triangulation of the projected points.
   * Range [2, 3].
   */
  vtkSetClampMacro(Dimension, int, 2, 3);
  vtkGetMacro(Dimension, int);
  ///@}

  ///@{
  /**
   * Plane onto which the points are projected in 2.5D mode: XY_PLANE (0, default) or
   * BEST_FIT_PLANE (1, the least-squares plane of the points). Range [0, 1]. Ignored in 3D.
   */
  vtkSetClampMacro(ProjectionPlane, int, XY_PLANE, BEST_FIT_PLANE);
  vtkGetMacro(ProjectionPlane, int);
  void SetProjectionPlaneToXYPlane() { this->SetProjectionPlane(XY_PLANE); }
  void SetProjectionPlaneToBestFitPlane() { this->SetProjectionPlane(BEST_FIT_PLANE); }
  ///@}

  ///@{
  /**
   * Absolute distance below which two points are merged before triangulation. Default 0:
   * only exact duplicates are merged. Range [0, VTK_DOUBLE_MAX]. Merging is greedy in input
   * order: a point joins the first kept point within Tolerance.
   */
  vtkSetClampMacro(Tolerance, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Tolerance, double);
  ///@}

  ///@{
  /**
   * Produce the tetrahedra (triangles in 2.5D) on output port 1. Default on.
   */
  vtkSetMacro(GenerateTetrahedra, bool);
  vtkGetMacro(GenerateTetrahedra, bool);
  vtkBooleanMacro(GenerateTetrahedra, bool);
  ///@}

  ///@{
  /**
   * Produce the Voronoi diagram on output port 2. Default off (it is about three times the
   * size of the tetrahedralization).
   */
  vtkSetMacro(GenerateVoronoi, bool);
  vtkGetMacro(GenerateVoronoi, bool);
  vtkBooleanMacro(GenerateVoronoi, bool);
  ///@}

  ///@{
  /**
   * Counts from the last execution: input points, points merged into another (duplicates),
   * points skipped (non-finite coordinates), and cells (tetrahedra, or triangles in 2.5D).
   */
  vtkGetMacro(NumberOfInputPoints, vtkIdType);
  vtkGetMacro(NumberOfDuplicatePoints, vtkIdType);
  vtkGetMacro(NumberOfSkippedPoints, vtkIdType);
  vtkGetMacro(NumberOfCells, vtkIdType);
  ///@}

  ///@{
  /**
   * Convenience access to the outputs: the hull / terrain surface (port 0), the
   * tetrahedralization (port 1) and the Voronoi diagram (port 2).
   */
  vtkPolyData* GetSurfaceOutput();
  vtkUnstructuredGrid* GetTetrahedraOutput();
  vtkPolyData* GetVoronoiOutput();
  ///@}

protected:
  vtkIncrementalDelaunay3D();
  ~vtkIncrementalDelaunay3D() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Dimension = 3;
  int ProjectionPlane = XY_PLANE;
  double Tolerance = 0.0;
  bool GenerateTetrahedra = true;
  bool GenerateVoronoi = false;

  vtkIdType NumberOfInputPoints = 0;
  vtkIdType NumberOfDuplicatePoints = 0;
  vtkIdType NumberOfSkippedPoints = 0;
  vtkIdType NumberOfCells = 0;

private:
  vtkIncrementalDelaunay3D(const vtkIncrementalDelaunay3D&) = delete;
  void operator=(const vtkIncrementalDelaunay3D&) = delete;
};

#endif
