// One-value field data arrays (counts and measures) that the filters attach to their outputs
// (private helper, not wrapped).
#ifndef pcsFieldData_h
#define pcsFieldData_h

#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"

namespace pcs
{
/// Adds (or replaces) the one-value vtkIdTypeArray `name` = `value`.
inline void AddFieldCount(vtkFieldData* fd, const char* name, vtkIdType value)
{
  vtkNew<vtkIdTypeArray> array;
  array->SetName(name);
  array->SetNumberOfValues(1);
  array->SetValue(0, value);
  fd->AddArray(array);
}

/// Adds (or replaces) the one-value vtkDoubleArray `name` = `value`.
inline void AddFieldValue(vtkFieldData* fd, const char* name, double value)
{
  vtkNew<vtkDoubleArray> array;
  array->SetName(name);
  array->SetNumberOfValues(1);
  array->SetValue(0, value);
  fd->AddArray(array);
}
} // namespace pcs

#endif
