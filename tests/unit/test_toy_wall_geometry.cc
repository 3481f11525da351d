// A new wall geometry is one file and one registration line (walls/wall_geometry.h): this test is
// that file. Its toy geometry is a regular tetrahedron of edge a with one vertex at the origin,
// with its own parameter (Wall NAME/Tetrahedron edge). Registered here, outside the library, it
// must be a choice of Geometry, have its parameter declared (on the walls that chose it, and
// only there) and read, and make a wall the wall then places, without a change anywhere else.
//
// The truth: four equilateral triangles of edge a, total area sqrt(3) a^2, their vertices at
// R p + Offset for the tetrahedron's own p (Rotation axis and angle, Offset: the wall's).
#include <abrade/common/error.h>
#include <abrade/coupling/parameters/parameter_file.h>
#include <abrade/coupling/parameters/parameters.h>
#include <abrade/coupling/walls/wall_geometry.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

namespace
{
  using namespace abrade::coupling;
  using abrade::dem::Vec3;

  class Tetrahedron : public WallGeometry
  {
  public:
    std::string name() const override { return "tetrahedron"; }
    std::string documentation() const override { return "a regular tetrahedron, a vertex at the origin"; }
    void        declare_parameters(abrade::dem::ParameterSection &p) const override
    {
      p.declare_number("Tetrahedron edge", 0.1, 1e-6, 10, "[m] Its edge length. Range: [1e-6, 10].");
    }
    WallShape make(const abrade::dem::ParameterSection &p, const WallGeometryContext &) const override
    {
      WallShape shape;
      for (const auto &v : vertices(p.number("Tetrahedron edge")))
        shape.mesh.vertices.push_back(v);
      shape.mesh.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
      return shape;
    }
    static std::vector<Vec3> vertices(double a)
    {
      return {Vec3(0, 0, 0), Vec3(a, 0, 0), Vec3(a / 2, a * std::sqrt(3.0) / 2, 0),
              Vec3(a / 2, a * std::sqrt(3.0) / 6, a * std::sqrt(2.0 / 3.0))};
    }
  };

  const DemCase::WallCase &wall_named(const DemCase &c, const std::string &name)
  {
    for (const auto &w : c.walls)
      if (w.wall.name == name)
        return w;
    throw std::runtime_error("no wall " + name);
  }

  /// The lines of subsection "Wall NAME" of a canonical parameter text, its own entries only.
  std::string wall_block(const std::string &text, const std::string &name)
  {
    const auto a = text.find("subsection Wall " + name + "\n");
    return a == std::string::npos ? "" : text.substr(a, text.find("\nend", a) - a);
  }

  std::string write(const std::filesystem::path &file, const std::string &text)
  {
    std::ofstream(file) << text;
    return file.string();
  }
} // namespace

ABRADE_REGISTER_WALL_GEOMETRY(Tetrahedron);

// a choice of Geometry beside the library's own, in the order of the names
TEST(ToyWallGeometry, IsRegisteredWithTheBuiltInOnes)
{
  std::vector<std::string> names;
  for (const auto &g : make_wall_geometries())
    names.push_back(g->name());
  EXPECT_NE(std::find(names.begin(), names.end(), "tetrahedron"), names.end());
  EXPECT_NE(std::find(names.begin(), names.end(), "box"), names.end());
  EXPECT_TRUE(std::is_sorted(names.begin(), names.end()));
}

// a wall of the default case given it: its parameter read, its triangles placed by the wall
TEST(ToyWallGeometry, MakesAWallTheWallPlaces)
{
  const double  a = 0.3;
  ParameterFile params("", {"Wall container/Geometry=tetrahedron", "Wall container/Tetrahedron edge=0.3",
                            "Wall container/Rotation axis=0, 0, 1", "Wall container/Rotation angle=90",
                            "Wall container/Offset=1, 2, 3"});
  const DemCase c    = read_dem_case(params);
  const auto   &mesh = wall_named(c, "container").wall.mesh;
  ASSERT_EQ(mesh.n_triangles(), 4u);
  double area = 0;
  for (const auto &t : mesh.triangles)
    area += 0.5 * (mesh.vertices[t[1]] - mesh.vertices[t[0]]).cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]).norm();
  EXPECT_NEAR(area, std::sqrt(3.0) * a * a, 1e-12);
  const auto own = Tetrahedron::vertices(a);
  for (std::size_t k = 0; k < own.size(); ++k) // a quarter turn about z: (x, y, z) -> (-y, x, z)
    EXPECT_LT((mesh.vertices[k] - (Vec3(-own[k].y(), own[k].x(), own[k].z()) + Vec3(1, 2, 3))).norm(), 1e-12) << k;
}

// a built-in geometry refuses a size its mesh cannot have, naming the entry (a shell of no
// width or radius was meshed into triangles of no area)
TEST(ToyWallGeometry, AShellOfNoSizeIsRefused)
{
  for (const char *entry : {"Shell radius", "Shell width"})
    try
      {
        ParameterFile params("", {"Wall container/Geometry=clamshell shell", std::string("Wall container/") + entry + "=0"});
        read_dem_case(params);
        ADD_FAILURE() << entry << " = 0 was accepted";
      }
    catch (const abrade::InputError &e)
      {
        EXPECT_NE(std::string(e.what()).find(std::string(entry) + ": a shell needs a positive size"), std::string::npos)
          << e.what();
      }
}

// a wall has its own geometry's entries only: in the run's record, and set on another wall's
TEST(ToyWallGeometry, AWallHasItsOwnGeometrysEntriesOnly)
{
  ParameterFile params("", {"Wall container/Geometry=tetrahedron"});
  const std::string text      = params.canonical_text();
  const std::string container = wall_block(text, "container"), knife = wall_block(text, "knife");
  ASSERT_FALSE(container.empty());
  ASSERT_FALSE(knife.empty());
  EXPECT_NE(container.find("Tetrahedron edge"), std::string::npos);
  EXPECT_EQ(container.find("Box min"), std::string::npos);
  EXPECT_EQ(knife.find("Tetrahedron edge"), std::string::npos); // (a solid model)
  EXPECT_NE(knife.find("Mounted on"), std::string::npos);
  EXPECT_EQ(knife.find("Shell radius"), std::string::npos);
  // another geometry's entry set on the wall is refused, saying whose it is
  try
    {
      ParameterFile bad("", {"Wall container/Geometry=tetrahedron", "Wall container/Box min=0, 0, 0"});
      FAIL() << "Box min on a tetrahedron was accepted";
    }
  catch (const abrade::InputError &e)
    {
      EXPECT_NE(std::string(e.what()).find("'Box min' is an entry of Geometry = box, and wall container's Geometry is "
                                           "tetrahedron"),
                std::string::npos)
        << e.what();
    }
}

// an included base case whose wall the including file makes another geometry: the base's
// entries of the old geometry are left out, and said; set beside the choice, refused
TEST(ToyWallGeometry, ABaseCasesEntriesOfAnotherGeometryAreLeftOut)
{
  const auto dir = std::filesystem::temp_directory_path() / ("abrade_toy_geometry_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  write(dir / "base.prm", "set Walls = w\n"
                          "subsection Wall w\n"
                          "  set Geometry = chisel knife\n"
                          "  set Knife length = 0.5\n"
                          "  set Offset = 0, 0, 0.2\n"
                          "end\n");
  const std::string top = write(dir / "top.prm", "include base.prm\n"
                                                 "subsection Wall w\n"
                                                 "  set Geometry = tetrahedron\n"
                                                 "end\n");
  ParameterFile params(top, {});
  ASSERT_EQ(params.notes().size(), 1u);
  EXPECT_NE(params.notes()[0].find("Wall w: left out"), std::string::npos) << params.notes()[0];
  EXPECT_NE(params.notes()[0].find("Knife length (" + (dir / "base.prm").string() + ":4)"), std::string::npos)
    << params.notes()[0];
  const DemCase c = read_dem_case(params);
  EXPECT_EQ(wall_named(c, "w").wall.mesh.n_triangles(), 4u);
  EXPECT_NEAR(wall_named(c, "w").offset.z(), 0.2, 1e-15); // (the base's other entries hold)
  // the same entry in the file that chose the geometry is the user's mistake: refused
  const std::string beside = write(dir / "beside.prm", "include base.prm\n"
                                                       "subsection Wall w\n"
                                                       "  set Geometry = tetrahedron\n"
                                                       "  set Knife length = 0.5\n"
                                                       "end\n");
  EXPECT_THROW(ParameterFile(beside, {}), abrade::InputError);
  // an entry of another geometry after the base's own choice is the user's too: refused
  const std::string after = write(dir / "after.prm", "include base.prm\n"
                                                     "subsection Wall w\n"
                                                     "  set Box min = 0, 0, 0\n"
                                                     "end\n");
  EXPECT_THROW(ParameterFile(after, {}), abrade::InputError);
  // chosen on the command line, the file's entries are the base
  ParameterFile chosen(write(dir / "plain.prm", "include base.prm\n"), {"Wall w/Geometry=tetrahedron"});
  EXPECT_EQ(chosen.notes().size(), 1u);
  std::filesystem::remove_all(dir);
}

// what abrade writes it reads back: `abrade params --format prm` (and a parameters.prm of an
// earlier version) has every geometry's and motion's entries at their defaults, no-ops that are
// left out without a word
TEST(ToyWallGeometry, ReadsTheReferenceOfEveryEntryBack)
{
  ParameterFile     reference;
  const auto        dir  = std::filesystem::temp_directory_path() / ("abrade_toy_reference_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string file = write(dir / "every_entry.prm", reference.canonical_text());
  ASSERT_NE(reference.canonical_text().find("Shell radius"), std::string::npos);
  ParameterFile params(file, {});
  EXPECT_TRUE(params.notes().empty());
  EXPECT_EQ(read_dem_case(params).walls.size(), 2u);
  // one of them not at its default is the user's: refused
  std::string changed = reference.canonical_text();
  changed.replace(changed.find("Shell radius"), 0, "Shell radius = 0.7\n  set ");
  EXPECT_THROW(ParameterFile(write(dir / "changed.prm", changed), {}), abrade::InputError);
  std::filesystem::remove_all(dir);
}

// deal.II's ways of writing a line: continued with '\\' (with blanks after it, or Windows line
// ends), keywords in capitals; and a --set that repeats the file's own choice replaces nothing
TEST(ToyWallGeometry, LeavesOutWhatDealIIReadsAsOneEntry)
{
  const auto dir = std::filesystem::temp_directory_path() / ("abrade_toy_lines_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  write(dir / "base.prm", "SET Walls = w\r\n"
                          "SUBSECTION Wall w\r\n"
                          "  SET Geometry = plate\r\n"
                          "  set Plate centre = 0, 0, \\ \r\n"
                          "     0.5\r\n"
                          "  set Plate size = 0.5, \\\r\n"
                          "     0.5\r\n"
                          "END\r\n");
  ParameterFile params(write(dir / "top.prm", "include base.prm\nsubsection Wall w\n  set Geometry = box\nend\n"), {});
  ASSERT_EQ(params.notes().size(), 1u);
  EXPECT_NE(params.notes()[0].find("as entries of Geometry = plate, which "), std::string::npos) << params.notes()[0];
  EXPECT_NE(params.notes()[0].find("replaced by box: Plate centre (" + (dir / "base.prm").string() + ":4), Plate size ("),
            std::string::npos)
    << params.notes()[0];
  EXPECT_EQ(wall_named(read_dem_case(params), "w").wall.mesh.n_triangles(), 10u); // (the box)

  // in the order a parameters.prm is written (Bevel height before Geometry), with a tab after
  // set: the block's own choice holds for the whole block
  const std::string sorted = write(dir / "sorted.prm", "set Walls = w\n"
                                                       "subsection Wall w\n"
                                                       "  set\tBevel height = 0.05\n"
                                                       "  set Geometry = chisel knife\n"
                                                       "end\n");
  ParameterFile replaced(sorted, {"Wall w/Geometry=tetrahedron"});
  ASSERT_EQ(replaced.notes().size(), 1u);
  EXPECT_NE(replaced.notes()[0].find("Bevel height (" + sorted + ":3)"), std::string::npos) << replaced.notes()[0];

  write(dir / "mistake.prm", "set Walls = w\n"
                             "subsection Wall w\n"
                             "  set Geometry = plate\n"
                             "  set Box min = 0, 0, 0\n"
                             "end\n");
  EXPECT_THROW(ParameterFile((dir / "mistake.prm").string(), {"Wall w/Geometry=plate"}), abrade::InputError);
  std::filesystem::remove_all(dir);
}
