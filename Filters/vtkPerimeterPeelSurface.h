/**
 * @class   vtkPerimeterPeelSurface
 * @brief   Surface of a point cloud by peeling its Delaunay tetrahedralization from the convex
 *          hull inwards (Rodriguez, Espadero, Lopez, Pastor, DGCI 2000, section 3)
 *
 * The input is any vtkPointSet; only its points matter. The points are tetrahedralized exactly
 * (the kernel of vtkIncrementalDelaunay3D; NaN/Inf points are skipped, exact duplicates merged)
 * and the solid made of the tetrahedra is peeled (paper section 3, steps 2-7):
 *
 * - the exterior facets are the facets of the solid that only one of its tetrahedra owns; at the
 *   start, the convex hull (step 3);
 * - threshold = mean measure of the exterior facets x ThresholdFactor (step 4), or Threshold
 *   when it is positive (a fixed threshold, the paper's user threshold: a single pass);
 * - every exterior facet over the threshold removes the tetrahedron that owns it, whose other
 *   facets become exterior (steps 5-6); the largest facets go first (a priority queue), so
 *   the result does not depend on the input order and each tetrahedron is removed at most once:
 *   O(n log n) after the tetrahedralization;
 * - the mean is recomputed; while it moved by more than ConvergenceTolerance (relative), the
 *   threshold is updated and peeling continues (step 7), at most MaximumIterations times.
 *
 * The facet measure is FacetMeasure: the perimeter (the paper's choice, default), the area or
 * the circumradius (the alternatives the paper weighs).
 *
 * Beyond the paper:
 * - No point is lost by peeling: a tetrahedron is kept when removing it would leave one of its
 *   vertices in no tetrahedron (the paper's "loss of vertices"). Points that the surface still
 *   does not use (inside the solid, or duplicates) have point data `Used` = 0 and are counted.
 * - ManifoldOutput (default on): the surface has no non-manifold edge or vertex. After peeling,
 *   every vertex or edge where the solid pinches is resolved by restoring the removed (finite)
 *   tetrahedra around it, which never loses a point (peeling further would), until none is
 *   left; restoring only adds tetrahedra, so this terminates (at worst at the convex hull).
 * - The triangles are oriented consistently, outward from the solid.
 *
 * Caveat (paper section 3): the threshold is global; on clouds whose density varies a lot, the
 * sparse regions open (holes) or the dense ones keep spurious tetrahedra. ThresholdFactor
 * between 1 and 2 helps, as the paper suggests.
 *
 * Output: a vtkPolyData with ALL input points and their point data, point data `Used`
 * (unsigned char) and field data NumberOfIterations, FinalThreshold (input units),
 * NumberOfTetrahedra, NumberOfRemovedTetrahedra, NumberOfRestoredTetrahedra,
 * NumberOfTriangles, NumberOfUsedPoints, NumberOfUnusedPoints.
 *
 * Under MPI the cloud is gathered on process 0, which computes the surface; the other
 * processes' outputs are empty.
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
  /// The measure of a facet: PERIMETER (default, the paper's choice), AREA or CIRCUMRADIUS.
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
  /// Resolve the solid's pinches so that the surface has no non-manifold edge or vertex.
  /// Default on.
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
  bool ManifoldOutput = true;

private:
  vtkPerimeterPeelSurface(const vtkPerimeterPeelSurface&) = delete;
  void operator=(const vtkPerimeterPeelSurface&) = delete;
};

#endif
