// Output infrastructure: JSON summary, CSV, VTK XML (.vtp) and .pvd series, progress line.
#include <abrade/common/csv_writer.h>
#include <abrade/common/hash.h>
#include <abrade/common/json.h>
#include <abrade/common/list_items.h>
#include <abrade/common/output_directory.h>
#include <abrade/common/progress.h>
#include <abrade/common/vtk_output.h>
#include <abrade/dem/mesh_io.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace abrade;

namespace
{
  std::string slurp(const std::string &p)
  {
    std::ifstream      in(p);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }
  std::string tmp(const std::string &name) { return (std::filesystem::temp_directory_path() / name).string(); }
} // namespace

TEST(Json, NestedObjectsArraysAndEscapes)
{
  io::Json j;
  j["name"]          = "knife \"A\"\n";
  j["n"]             = 3;
  j["ok"]            = true;
  j["x"]             = std::vector<double>{1.5, 2};
  j["nested"]["nan"] = std::nan("");
  j["nested"]["v"]   = 1e-300;
  EXPECT_EQ(j.dump(0), "{\"name\":\"knife \\\"A\\\"\\n\",\"n\":3,\"ok\":true,\"x\":[1.5, 2],"
                       "\"nested\":{\"nan\":null,\"v\":1e-300}}\n");
}

TEST(Csv, HeaderRowsAndWidthCheck)
{
  const std::string p = tmp("abrade_test.csv");
  {
    io::CsvWriter c(p, {"phase", "a", "b"});
    c.row("travel", {1.25, -2});
    EXPECT_THROW(c.row({1.0}), std::logic_error);
  }
  EXPECT_EQ(slurp(p), "phase,a,b\ntravel,1.25,-2\n");
  std::filesystem::remove(p);
}

// A row by column name: written in the header's order whatever the pairs' order; a column
// missing, unknown or given twice is a bug, named (trajectory.csv's rows are built this way).
TEST(Csv, RowsByColumnName)
{
  const std::string p = tmp("abrade_test_named.csv");
  {
    io::CsvWriter c(p, {"update", "tonnes", "depth"});
    EXPECT_EQ(c.named_row({{"depth", 0.5}, {"update", 1}, {"tonnes", 400}}), "1,400,0.5");
    EXPECT_THROW(c.named_row({{"update", 2}, {"tonnes", 800}}), std::logic_error);
    EXPECT_THROW(c.named_row({{"update", 2}, {"tonnes", 800}, {"depth", 1}, {"mass", 3}}), std::logic_error);
    EXPECT_THROW(c.named_row({{"update", 2}, {"update", 3}, {"tonnes", 800}}), std::logic_error);
  }
  EXPECT_EQ(slurp(p), "update,tonnes,depth\n1,400,0.5\n");
  std::filesystem::remove(p);
}

TEST(Vtk, PolyDataAndPvdSeries)
{
  const std::string dir = tmp("abrade_vtk_test");
  io::OutputDirectory out(dir);
  io::PolyData d;
  d.points    = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
  d.triangles = {{0, 1, 2}, {1, 3, 2}};
  d.cell_fields.push_back({"wear", 1, {0.5, 0.25}});
  d.point_fields.push_back({"velocity", 3, std::vector<double>(12, 1.0)});
  io::write_vtp(out.file("surface.vtp"), d);
  // read back through VTK: two triangles, four points
  const auto mesh = dem::read_surface_mesh(out.file("surface.vtp"));
  EXPECT_EQ(mesh.n_triangles(), 2u);
  EXPECT_EQ(mesh.vertices.size(), 4u);
  EXPECT_THROW((io::write_vtp(out.file("bad.vtp"), io::PolyData{{0, 0, 0}, {}, {{"f", 1, {1, 2}}}, {}})),
               std::logic_error);

  io::PvdSeries series(out.file("s.pvd"));
  series.add(0.0, "a.vtp");
  series.add(0.5, "b.vtp");
  const std::string pvd = slurp(out.file("s.pvd"));
  EXPECT_NE(pvd.find("timestep=\"0.5\" group=\"\" part=\"0\" file=\"b.vtp\""), std::string::npos);
  EXPECT_NE(pvd.find("</VTKFile>"), std::string::npos);
  std::filesystem::remove_all(dir);
}

TEST(ListItems, SplitTrimmedWithoutEmpties)
{
  using V = std::vector<std::string>;
  EXPECT_EQ(io::list_items("opening, closing", ','), (V{"opening", "closing"}));
  EXPECT_EQ(io::list_items(" a ,\tb\t,, c,", ','), (V{"a", "b", "c"})); // tabs too, empty items left out
  EXPECT_EQ(io::list_items("", ','), V{});
  EXPECT_EQ(io::list_items(" , ,", ','), V{});
  EXPECT_EQ(io::list_items("one", ','), V{"one"});
  EXPECT_EQ(io::list_items("x=1; y = 2", ';'), (V{"x=1", "y = 2"})); // (only the ends trimmed)
}

TEST(Hash, StableFnv1a)
{
  EXPECT_EQ(io::fnv1a_hex(""), "cbf29ce484222325");
  EXPECT_EQ(io::fnv1a_hex("a"), "af63dc4c8601ec8c");
}

TEST(Progress, DurationsAndQuietWhenNotATerminal)
{
  EXPECT_EQ(io::ProgressLine::format_duration(5), "5s");
  EXPECT_EQ(io::ProgressLine::format_duration(185), "3m05s");
  EXPECT_EQ(io::ProgressLine::format_duration(3725), "1h02m");
  // under ctest stderr is not a terminal: nothing may be drawn
  EXPECT_FALSE(io::ProgressLine::enabled());
}
