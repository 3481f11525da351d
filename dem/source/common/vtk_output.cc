// VTK XML output: .vtp surfaces and point sets with fields, .pvd series, STL (vtk_output.h).
#include <abrade/common/atomic_file.h>
#include <abrade/common/error.h>
#include <abrade/common/vtk_output.h>

#include "vtk_polydata.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkSTLWriter.h>
#include <vtkXMLPolyDataWriter.h>

#include <fstream>
#include <sstream>
#include <iomanip>

namespace abrade::io
{
  namespace
  {
    vtkNew<vtkDoubleArray> make_array(const Field &f, std::size_t expected_tuples,
                                      const std::string &path)
    {
      if (f.values.size() != expected_tuples * f.n_components)
        throw std::logic_error("field " + f.name + " has the wrong size for " + path);
      vtkNew<vtkDoubleArray> a;
      a->SetName(f.name.c_str());
      a->SetNumberOfComponents(f.n_components);
      a->SetNumberOfTuples(expected_tuples);
      std::copy(f.values.begin(), f.values.end(), a->GetPointer(0));
      return a;
    }
  } // namespace

  vtkSmartPointer<vtkPolyData> to_vtk(const PolyData &data, const std::string &path)
  {
    const std::size_t n_points = data.points.size() / 3;
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(n_points);
    for (std::size_t i = 0; i < n_points; ++i)
      points->SetPoint(i, &data.points[3 * i]);

    auto poly = vtkSmartPointer<vtkPolyData>::New();
    poly->SetPoints(points);
    vtkNew<vtkCellArray> cells;
    std::size_t          n_cells;
    if (data.triangles.empty())
      {
        for (std::size_t i = 0; i < n_points; ++i)
          {
            vtkIdType id = i;
            cells->InsertNextCell(1, &id);
          }
        poly->SetVerts(cells);
        n_cells = n_points;
      }
    else
      {
        for (const auto &t : data.triangles)
          {
            vtkIdType ids[3] = {t[0], t[1], t[2]};
            cells->InsertNextCell(3, ids);
          }
        poly->SetPolys(cells);
        n_cells = data.triangles.size();
      }
    for (const auto &f : data.point_fields)
      poly->GetPointData()->AddArray(make_array(f, n_points, path));
    for (const auto &f : data.cell_fields)
      poly->GetCellData()->AddArray(make_array(f, n_cells, path));
    return poly;
  }

  void write_vtp(const std::string &path, const PolyData &data)
  {
    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->SetFileName(path.c_str());
    writer->SetInputData(to_vtk(data, path));
    writer->SetDataModeToBinary();
    if (writer->Write() != 1)
      throw RunError("cannot write " + path);
  }

  void write_stl(const std::string &path, const PolyData &data)
  {
    vtkNew<vtkSTLWriter> writer;
    writer->SetFileName(path.c_str());
    writer->SetInputData(to_vtk(data, path));
    writer->SetFileTypeToBinary();
    if (writer->Write() != 1)
      throw RunError("cannot write " + path);
  }

  void PvdSeries::add(double time, const std::string &file)
  {
    entries.emplace_back(time, file);
    std::ostringstream out;
    out << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
        << "  <Collection>\n"
        << std::setprecision(10);
    for (const auto &[t, f] : entries)
      out << "    <DataSet timestep=\"" << t << "\" group=\"\" part=\"0\" file=\"" << f
          << "\"/>\n";
    out << "  </Collection>\n</VTKFile>\n";
    write_file_atomically(path, out.str()); // checked; a kill leaves the old series or the new one
  }
} // namespace abrade::io
