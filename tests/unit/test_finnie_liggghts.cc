// Finnie wear against the peer code: the same oblique impact of one pellet on a two-triangle
// plate, run by LIGGGHTS-PUBLIC (`fix mesh/surface/stress ... wear finnie`, dumped with
// `dump mesh/vtk ... wear`) and by abrade, gives the same per-triangle wear. Skipped when
// `liggghts` is not installed.
#include "dem_test_helpers.h"

#include <abrade/dem/mesh_io.h>
#include <abrade/dem/wear.h>

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace abrade::dem;
using namespace abrade::dem::testing;

namespace
{
  const char *plate_stl = R"(solid plate
facet normal 0 0 1
 outer loop
  vertex -0.1 -0.1 0
  vertex 0.1 -0.1 0
  vertex 0.1 0.1 0
 endloop
endfacet
facet normal 0 0 1
 outer loop
  vertex -0.1 -0.1 0
  vertex 0.1 0.1 0
  vertex -0.1 0.1 0
 endloop
endfacet
endsolid plate
)";

  // pellets (type 1: E 2.5e8, nu 0.25, 3700 kg/m^3, r 27.5 mm) on steel (type 2: E 1.82e11,
  // nu 0.3); restitution 0.6, friction 0.4, k_finnie 1; no gravity, no rotation; dt 1e-5
  const char *input = R"(atom_style granular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
units si
hard_particles yes
region domain block -0.5 0.5 -0.5 0.5 -0.2 0.5 units box
create_box 2 domain
neighbor 0.01 bin
neigh_modify delay 0
fix m1 all property/global youngsModulus peratomtype 2.5e8 1.82e11
fix m2 all property/global poissonsRatio peratomtype 0.25 0.3
fix m3 all property/global coefficientRestitution peratomtypepair 2 0.6 0.6 0.6 0.6
fix m4 all property/global coefficientFriction peratomtypepair 2 0.5 0.4 0.4 0.5
fix m6 all property/global k_finnie peratomtypepair 2 1.0 1.0 1.0 1.0
pair_style gran model hertz tangential history
pair_coeff * *
timestep 1e-5
fix plate all mesh/surface/stress file plate.stl type 2 wear finnie
fix wall all wall/gran model hertz tangential history mesh n_meshes 1 meshes plate
create_atoms 1 single 0.03 -0.05 0.0280 units box
set atom 1 diameter 0.055 density 3700
velocity all set VX 0.0 VZ units box
fix integr all nve
dump d all mesh/vtk 1000 plate*.vtk wear
run 1000
)";

  std::vector<double> liggghts_wear(const std::string &dir, double vx, double vz)
  {
    std::filesystem::create_directories(dir);
    std::ofstream(dir + "/plate.stl") << plate_stl;
    std::string in = input;
    in.replace(in.find("VX"), 2, std::to_string(vx));
    in.replace(in.find("VZ"), 2, std::to_string(vz));
    std::ofstream(dir + "/impact.in") << in;
    const std::string cmd = "cd '" + dir + "' && liggghts -in impact.in -log log.lig -screen screen.log > /dev/null 2>&1";
    if (std::system(cmd.c_str()) != 0)
      return {};
    std::ifstream vtk(dir + "/plate1000.vtk");
    std::string   word;
    while (vtk >> word)
      if (word == "wear")
        {
          int         components, n;
          std::string type;
          vtk >> components >> n >> type;
          std::vector<double> w(n);
          for (auto &x : w)
            vtk >> x;
          return w;
        }
    return {};
  }

  std::vector<double> abrade_wear(const std::string &dir, double vx, double vz)
  {
    Simulation sim(quiet_settings(1e-5));
    const int  mp = sim.add_material({"pellet", 2.5e8, 0.25, 3700, false});
    const int  mw = sim.add_material({"steel", 1.82e11, 0.3, 7800, false});
    sim.set_interaction(mp, mp, {0.6, 0.5, 0.0});
    sim.set_interaction(mp, mw, {0.6, 0.4, 0.0});
    Wall w;
    w.name = "plate", w.mesh = read_surface_mesh(dir + "/plate.stl"), w.material = mw;
    sim.add_wall(w);
    sim.particles().add(0, 0.03, -0.05, 0.028, 0.0275, 3700, mp);
    sim.particles().vx[0] = vx, sim.particles().vz[0] = vz;
    sim.setup();
    auto wear = std::make_shared<WearRecorder>(sim, std::vector<WallWearLaws>{{make_wear_law("finnie", {{"Coefficient", 1.0}})}});
    sim.add_hook(wear);
    sim.run_phase("impact", 1000 * 1e-5);
    return wear->values(0, "finnie_wear");
  }
} // namespace

TEST(FinnieAgainstLiggghts, SameImpactSameWearPerTriangle)
{
  if (std::system("command -v liggghts > /dev/null 2>&1") != 0)
    GTEST_SKIP() << "liggghts is not installed";
  const std::string dir = (std::filesystem::temp_directory_path() / "abrade_finnie_peer").string();
  // a glancing impact (angle 31 deg, Finnie's cos^2/3 branch) and a flatter one (14 deg, the
  // sin(2g) - 3 sin^2(g) branch)
  for (const auto &[vx, vz] : {std::pair{2.0, -1.2}, std::pair{3.0, -0.75}})
    {
      const auto peer = liggghts_wear(dir, vx, vz);
      ASSERT_EQ(peer.size(), 2u) << "could not read LIGGGHTS' wear dump in " << dir;
      const auto ours = abrade_wear(dir, vx, vz);
      std::printf("impact (%.2f, %.2f) m/s: Finnie wear LIGGGHTS %.6g %.6g, abrade %.6g %.6g\n", vx, vz, peer[0],
                  peer[1], ours[0], ours[1]);
      ASSERT_GT(peer[0], 0);
      EXPECT_NEAR(ours[0] / peer[0], 1, 1e-3); // measured: 5e-6
      EXPECT_EQ(peer[1], 0);
      EXPECT_EQ(ours[1], 0);
    }
  std::filesystem::remove_all(dir);
}
