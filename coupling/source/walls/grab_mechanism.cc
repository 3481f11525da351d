// The subsection "Grab mechanism" (walls/grab_mechanism.h).
#include <abrade/coupling/parameters/parameter_section.h>
#include <abrade/coupling/walls/grab_mechanism.h>
#include <abrade/dem/rope_grab_driver.h>

#include <algorithm>
#include <cmath>

namespace abrade::coupling
{
  void declare_grab_mechanism(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Grab mechanism");
    prm.declare_entry("Type", "none", dealii::Patterns::Selection("none|rope"),
                      "none: the walls move as their own Motion says; rope: a rope grab's mechanism moves the "
                      "walls of its shells and heads (upper head with holding ropes, closing rope reeved "
                      "between the heads, tie rods to the shells; docs/grab.md), under the particles' loads, "
                      "gravity and its winches.");
    PluginSection section(prm);
    dem::declare_rope_grab_parameters(section);
    prm.leave_subsection();
  }

  namespace
  {
    /// The entry that lists the walls of @p part.
    const char *key_of(dem::RopeGrab::Part part)
    {
      switch (part)
        {
          case dem::RopeGrab::Part::right_shell:
            return "Right shell walls";
          case dem::RopeGrab::Part::left_shell:
            return "Left shell walls";
          case dem::RopeGrab::Part::lower_head:
            return "Lower head walls";
          default:
            return "Upper head walls";
        }
    }

    /// A parametric shell's origin is its hinge: the mechanism must turn it about that, on its
    /// own side, and its lips (or its knives' edges) must not pass each other. (A shell from a
    /// file is not checked: its hinge and lip are the user's to place.)
    void check_parametric_shell(ParameterFile &f, const DemCase &c, const DemCase::WallCase &wc,
                                dem::RopeGrab::Part part, const dem::RopeGrabRig &rig)
    {
      const std::vector<std::string> path = {"Grab mechanism"};
      const std::string             &name = wc.wall.name;
      const dem::Vec3                hinge_of_wall = wc.offset;
      if (std::abs(hinge_of_wall.x() - rig.hinge.x()) > 1e-9 || std::abs(hinge_of_wall.z() - rig.hinge.z()) > 1e-9)
        f.fail(path, "Hinge",
               "the shell '" + name + "' turns about its hinge at its Offset (" + std::to_string(hinge_of_wall.x()) +
                 ", " + std::to_string(hinge_of_wall.y()) + ", " + std::to_string(hinge_of_wall.z()) +
                 "): the mechanism's Hinge must lie on that axis (the same x and z)");
      if ((wc.shell->side > 0) != (part == dem::RopeGrab::Part::right_shell))
        f.fail(path, key_of(part),
               "the shell '" + name + "' opens towards " + (wc.shell->side > 0 ? "+x" : "-x") +
                 ": the right shell is the +x one, the left the -x one");
      // the lips meet when the shells have turned by their opening from straight down; a knife
      // p beyond a lip of radius R reaches the middle atan(p / R) earlier
      double      meet = wc.shell->opening;
      std::string what = "its lip";
      for (const auto &knife : c.walls)
        if (knife.mount == name && wc.shell->opening - std::atan2(knife.protrusion, wc.shell->radius) < meet)
          {
            meet = wc.shell->opening - std::atan2(knife.protrusion, wc.shell->radius);
            what = "the edge of its knife '" + knife.wall.name + "'";
          }
      if (rig.design.closed_angle > meet + 1e-12)
        f.fail(path, "Closed angle",
               "the shell '" + name + "' would turn " + what + " past the middle beyond " +
                 std::to_string(meet * 180 / M_PI) + " degrees (its lip opens " +
                 std::to_string(wc.shell->opening * 180 / M_PI) + " degrees from straight down)");
    }

    /// The knives mounted on wall @p name (their Mounted on) ride with its @p part: added to
    /// @p rig, or refused where the mechanism lists them on another part.
    void add_mounted_knives(ParameterFile &f, const DemCase &c, const std::string &name, dem::RopeGrab::Part part,
                            dem::RopeGrabRig &rig)
    {
      for (const auto &knife : c.walls)
        if (knife.mount == name)
          {
            const auto listed = std::find_if(rig.walls.begin(), rig.walls.end(),
                                             [&](const auto &w) { return w.first == knife.wall.name; });
            if (listed == rig.walls.end())
              rig.walls.emplace_back(knife.wall.name, part);
            else if (listed->second != part)
              f.fail({"Grab mechanism"}, key_of(listed->second),
                     "'" + knife.wall.name + "' is mounted on '" + name + "' (its Mounted on) and rides with it");
          }
    }
  } // namespace

  void read_grab_mechanism(ParameterFile &f, DemCase &c)
  {
    auto &prm = f.handler();
    prm.enter_subsection("Grab mechanism");
    if (prm.get("Type") == "none")
      {
        prm.leave_subsection();
        return;
      }
    const std::vector<std::string> path = {"Grab mechanism"};
    std::vector<std::string>       phases;
    for (const auto &p : c.phases)
      phases.push_back(p.first);
    dem::RopeGrabRig rig = dem::parse_rope_grab_parameters(PluginSection(f, path), phases);
    prm.leave_subsection();

    const auto claimed = rig.walls;
    for (const auto &[name, part] : claimed)
      {
        const auto wc = std::find_if(c.walls.begin(), c.walls.end(), [&](const auto &w) { return w.wall.name == name; });
        if (wc == c.walls.end())
          f.fail(path, key_of(part), "'" + name + "' is not one of Walls");
        if (wc->wall.motion.kind != dem::WallMotion::Kind::fixed)
          f.fail({"Wall " + name, "Motion"}, "Type",
                 "the grab's mechanism moves this wall (Grab mechanism/" + std::string(key_of(part)) +
                   "): leave its Motion out");
        const bool shell = part == dem::RopeGrab::Part::right_shell || part == dem::RopeGrab::Part::left_shell;
        if (shell && wc->shell)
          check_parametric_shell(f, c, *wc, part, rig);
        add_mounted_knives(f, c, name, part, rig);
      }
    c.grab_mechanism = rig;
  }
} // namespace abrade::coupling
