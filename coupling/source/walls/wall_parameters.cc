// The subsection "Wall NAME": declared with the entries of the wall's own geometry and motion,
// read into the DEM's wall, and the mounted parts placed on their shells (wall_parameters.h).
#include <abrade/dem/parameter_section.h>
#include <abrade/common/format_number.h>
#include <abrade/coupling/parameters/material_parameters.h>
#include <abrade/coupling/parameters/parameter_section.h>
#include <abrade/coupling/walls/wall_parameters.h>
#include <abrade/dem/wall_motion_model.h>

#include <Eigen/Geometry>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

namespace abrade::coupling
{
  using dealii::ParameterHandler;
  using dealii::Utilities::split_string_list;
  using dealii::Utilities::trim;
  using dem::Vec3;

  namespace
  {
    Vec3 vec(const std::array<double, 3> &v) { return Vec3(v[0], v[1], v[2]); }

    /// The entries a plugin declares, with their defaults as a parameter file writes them.
    class DeclaredEntries : public dem::ParameterSection
    {
    public:
      std::map<std::string, std::string> defaults;

      void declare_number(const std::string &name, double value, double, double, const std::string &) override
      {
        defaults[name] = io::format_number(value, 15);
      }
      void declare_vector(const std::string &name, const std::array<double, 3> &v, const std::string &) override
      {
        defaults[name] =
          io::format_number(v[0], 15) + ", " + io::format_number(v[1], 15) + ", " + io::format_number(v[2], 15);
      }
      void declare_bool(const std::string &name, bool value, const std::string &) override
      {
        defaults[name] = value ? "true" : "false";
      }
      void declare_text(const std::string &name, const std::string &value, const std::string &) override
      {
        defaults[name] = value;
      }
      void declare_choices(const std::string &name, const std::string &value, const std::vector<std::string> &,
                           const std::string &) override
      {
        defaults[name] = value;
      }
      void declare_choice(const std::string &name, const std::string &value, const std::vector<std::string> &,
                          const std::string &) override
      {
        defaults[name] = value;
      }
      void declare_numbers(const std::string &name, const std::string &value, unsigned int, unsigned int, double,
                           double, const std::string &) override
      {
        defaults[name] = value;
      }
      double number(const std::string &name) const override
      {
        throw std::logic_error("parameter '" + name + "' read from a section that was only declared");
      }
      [[noreturn]] void fail(const std::string &name, const std::string &why) const override
      {
        throw std::logic_error("parameter '" + name + "': " + why);
      }
    };

    template <class Plugin>
    std::map<std::string, std::string> defaults_of(const Plugin &plugin)
    {
      DeclaredEntries declared;
      plugin.declare_parameters(declared);
      return declared.defaults;
    }

    void declare_geometry(ParameterHandler &prm, const WallChoices *choices)
    {
      const auto  geometries = make_wall_geometries();
      std::string names, doc; // "box (open-top container, ...), ..., or solid model (...)"
      for (std::size_t k = 0; k < geometries.size(); ++k)
        {
          const auto &g = geometries[k];
          names += (k == 0 ? "" : "|") + g->name();
          doc += std::string(k == 0 ? "" : k + 1 == geometries.size() ? ", or " : ", ") + g->name() + " (" +
                 g->documentation() + ")";
        }
      prm.declare_entry("Geometry", default_wall_choices("").geometry, dealii::Patterns::Selection(names),
                        "Wall geometry: " + doc + ". A wall takes the entries of its own geometry only.");
      PluginSection section(prm);
      for (const auto &g : geometries)
        if (!choices || g->name() == choices->geometry)
          g->declare_parameters(section);
      section.declare_vector("Offset", {0, 0, 0}, "[m] Translation applied to the geometry.");
      section.declare_vector("Rotation axis", {0, 0, 1},
                             "[-] Axis of a rotation of the geometry about the origin (right-handed), before Offset: "
                             "a point p of the geometry (a file's, in metres after File scale, or a primitive's) "
                             "becomes R p + Offset. 'Lip centre', its directions and Motion/Centre are given before "
                             "the rotation and turn with it; Motion/Velocities, Angular velocities and the Layer "
                             "probe's Axis are in the global frame and do not.");
      section.declare_number("Rotation angle", 0, -360, 360,
                             "[deg] Angle of that rotation; 0: none. Not for a part Mounted on a shell (the shell places it). "
                             "Range: [-360, 360].");
      section.declare_number("Maximum edge length", 0, 0, dem::unbounded,
                             "[m] Refine the mesh until no triangle edge is longer than this (per-"
                             "triangle wear needs triangles smaller than a particle); 0: as given. "
                             "Range: >= 0.");
      section.declare_bool("Flip normals", false, "Reverse the orientation of every triangle.");
    }

    void declare_wear(ParameterHandler &prm, const std::string &name)
    {
      prm.enter_subsection("Wear");
      std::string doc = "Wear laws evaluated per triangle of this wall (any of " + dem::wear_law_names() +
                        "; empty: none), each with its parameters in the subsection of its name; all are "
                        "reported per phase (docs/physics.md).";
      for (const auto &law : dem::registered_wear_laws())
        doc += " " + law->name() + ": " + law->documentation();
      prm.declare_entry("Laws", wall_defaults(name).wear_laws,
                        dealii::Patterns::List(dealii::Patterns::Selection(dem::wear_law_names("|"))), doc);
      for (const auto &law : dem::registered_wear_laws())
        {
          prm.enter_subsection(law->section());
          PluginSection section(prm);
          law->declare_parameters(section);
          prm.leave_subsection();
        }
      prm.leave_subsection();
    }

    void declare_layer_probe(ParameterHandler &prm, const std::string &name)
    {
      prm.enter_subsection("Layer probe");
      PluginSection section(prm);
      section.declare_bool("Enabled", wall_defaults(name).probe,
                           "Record the particles in direct contact with this wall (the thesis' "
                           "geometry bin, which moves with the wall): their number and mean velocity "
                           "along Axis, in walls/NAME_layer.csv.");
      section.declare_vector("Axis", {1, 0, 0}, "[-] Direction of the velocities the probe reports.");
      section.declare_number("Thickness", 0, 0, dem::unbounded,
                             "[m] Largest distance from the wall's surface to a particle centre in the "
                             "layer; 0: 1.5 x the largest particle radius (one layer). Range: >= 0.");
      section.declare_number("Interval", 0.001, 0, dem::unbounded,
                             "[s] Simulated time between probe samples; 0: every step. Range: >= 0.");
      prm.leave_subsection();
    }

    /// A motion's entries as a wall declares them: with the wall's own default for a text entry
    /// it names (the default case's knife moves without a Velocities line: wall_defaults()).
    class WithWallDefaults : public PluginSection
    {
    public:
      WithWallDefaults(ParameterHandler &prm, std::map<std::string, std::string> defaults)
        : PluginSection(prm), defaults(std::move(defaults))
      {}
      void declare_text(const std::string &name, const std::string &value, const std::string &doc) override
      {
        const auto own = defaults.find(name);
        PluginSection::declare_text(name, own == defaults.end() ? value : own->second, doc);
      }

    private:
      std::map<std::string, std::string> defaults;
    };

    void declare_motion(ParameterHandler &prm, const std::string &name, const WallChoices *choices)
    {
      prm.enter_subsection("Motion");
      const auto  motions = dem::make_wall_motions();
      std::string names, doc; // "fixed; prescribed: velocities per phase; ..."
      for (const auto &m : motions)
        {
          names += (names.empty() ? "" : "|") + m->name();
          doc += (doc.empty() ? "" : "; ") + m->name() + (m->documentation().empty() ? "" : ": " + m->documentation());
        }
      prm.declare_entry("Type", default_wall_choices(name).motion, dealii::Patterns::Selection(names),
                        doc + ". A wall takes the entries of its own motion only.");
      PluginSection section(prm);
      section.declare_vector("Centre", {0, 0, 0},
                             "[m] Rotation centre (a hinge point) in the geometry's coordinates before "
                             "Offset; it moves with the wall. Torques are reported about it.");
      // the chosen motion's own parameters (in Motion itself, or in its subsection; the velocity
      // table the prescribed and rigid-body motions')
      std::map<std::string, std::string> own_defaults;
      if (const std::string velocities = wall_defaults(name).velocities; !velocities.empty())
        own_defaults["Velocities"] = velocities;
      for (const auto &motion : motions)
        if (!choices || motion->name() == choices->motion)
          {
            if (!motion->section().empty())
              prm.enter_subsection(motion->section());
            WithWallDefaults own(prm, own_defaults);
            motion->declare_parameters(own);
            if (!motion->section().empty())
              prm.leave_subsection();
          }
      prm.leave_subsection();
    }

    /// The geometry's shape, placed (rotated, moved), refined and oriented as the wall says.
    void read_geometry(ParameterFile &f, const std::vector<std::string> &wp, DemCase &c, DemCase::WallCase &wc)
    {
      auto         &prm = f.handler();
      PluginSection section(f, wp);
      const auto    geometry = make_wall_geometry(prm.get("Geometry")); // (the pattern checked the name)
      WallGeometryContext context;
      context.path_beside         = [&f](const std::string &p) { return f.path_beside(p); };
      context.maximum_edge_length = section.number("Maximum edge length");
      WallShape shape             = geometry->make(section, context);
      for (auto &file : shape.input_files)
        c.input_files.push_back(file);

      const Vec3   offset = vec(section.vector("Offset")), axis = vec(section.vector("Rotation axis"));
      const double angle  = section.number("Rotation angle");
      if (angle != 0 && !(axis.norm() > 0))
        f.fail(wp, "Rotation axis", "must not be zero");
      if (angle != 0 && !shape.fixed_orientation.empty())
        f.fail(wp, "Rotation angle", shape.fixed_orientation);
      // placement: p -> rotation p + offset (the rotation about the origin first)
      wc.rotation    = angle == 0 ? Eigen::Matrix3d::Identity()
                                  : Eigen::AngleAxisd(angle * M_PI / 180, axis.normalized()).toRotationMatrix();
      wc.offset      = offset;
      wc.solid_model = shape.solid_model;
      wc.shell       = shape.shell;
      wc.mount       = shape.mount;
      wc.protrusion  = shape.protrusion;
      if (shape.lip)
        wc.lip = WallLip{wc.rotation * shape.lip->centre + offset, wc.rotation * shape.lip->along,
                         wc.rotation * shape.lip->inward};

      dem::TriangleMesh &mesh = wc.wall.mesh = std::move(shape.mesh);
      for (auto &v : mesh.vertices)
        v = wc.rotation * v;
      mesh.translate(offset);
      if (const double h = context.maximum_edge_length; h > 0)
        {
          // the triangles a refinement makes, about: each becomes ~ its area over that of an
          // equilateral triangle of edge h, at least itself
          double made = 0;
          for (const auto &t : mesh.triangles)
            {
              const Vec3 a = mesh.vertices[t[0]], b = mesh.vertices[t[1]], c3 = mesh.vertices[t[2]];
              made += std::max(1.0, 0.5 * (b - a).cross(c3 - a).norm() / (0.433 * h * h));
            }
          constexpr double most_triangles = 2e7;
          if (!(made <= most_triangles))
            f.fail(wp, "Maximum edge length",
                   "refining the wall's " + std::to_string(mesh.n_triangles()) + " triangles to edges of " +
                     std::to_string(h) + " m makes about " + std::to_string(long(std::min(made, 1e18))) +
                     " triangles, more than " + std::to_string(long(most_triangles)) +
                     " (each in every contact search): a longer edge, about the particle radius, is enough");
          mesh.refine(h);
        }
      if (section.boolean("Flip normals"))
        mesh.flip();
    }

    void read_wear(ParameterFile &f, const std::vector<std::string> &wp, const DemCase &c, DemCase::WallCase &wc)
    {
      auto &prm = f.handler();
      prm.enter_subsection("Wear");
      const std::vector<std::string> path = {wp[0], "Wear"};
      dem::WearContext               context;
      context.coarse_graining = c.coarse_graining;
      for (const auto &law_name : PluginSection(f, path).chosen("Laws"))
        {
          auto law = dem::make_wear_law(law_name); // (the pattern checked the name)
          if (law->uses_particle_size() && !c.finer_levels.empty())
            f.fail(path, "Laws",
                   "wear law " + law_name + " uses the real particle size, which a multi-level coarse graining "
                   "(Particles/Coarse graining/Fine region) gives two of: not supported");
          prm.enter_subsection(law->section());
          PluginSection section(f, {wp[0], "Wear", law->section()});
          law->parse_parameters(section, context);
          prm.leave_subsection();
          wc.wear.push_back(std::move(law));
        }
      prm.leave_subsection();
    }

    void read_layer_probe(ParameterFile &f, const std::vector<std::string> &wp, DemCase::WallCase &wc)
    {
      f.handler().enter_subsection("Layer probe");
      const PluginSection section(f, {wp[0], "Layer probe"});
      wc.probe           = section.boolean("Enabled");
      wc.probe_axis      = vec(section.vector("Axis"));
      wc.probe_thickness = section.number("Thickness");
      wc.probe_interval  = section.number("Interval");
      if (wc.probe && !(wc.probe_axis.norm() > 0))
        section.fail("Axis", "must not be zero");
      f.handler().leave_subsection();
    }

    void read_motion(ParameterFile &f, const std::vector<std::string> &wp, const DemCase &c, DemCase::WallCase &wc)
    {
      auto &prm = f.handler();
      prm.enter_subsection("Motion");
      const std::vector<std::string> mp = {wp[0], "Motion"};
      const PluginSection            section(f, mp);
      dem::WallMotion               &m = wc.wall.motion;
      m.centre                         = wc.rotation * vec(section.vector("Centre")) + wc.offset;
      std::shared_ptr<dem::WallMotionModel> motion = dem::make_wall_motion(prm.get("Type"));
      dem::MotionContext                    context;
      for (const auto &p : c.phases)
        context.phases.push_back(p.first);
      auto sp = mp;
      if (!motion->section().empty())
        {
          prm.enter_subsection(motion->section());
          sp.push_back(motion->section());
        }
      motion->parse_parameters(PluginSection(f, sp), context, m);
      if (!motion->section().empty())
        prm.leave_subsection();
      m.kind  = motion->kind();
      m.model = std::move(motion);
      prm.leave_subsection();
    }

    /// What coarse graining leaves unresolved or in absolute units on this wall.
    void warn_of_coarse_graining(const std::string &name, DemCase &c, const DemCase::WallCase &wc)
    {
      if (c.coarse_graining == 1 && c.finer_levels.empty())
        return;
      const double radius = c.particle_radius_at_tools(c.fill.sizes.largest()); // (before the bed exists)
      if (!wc.wear.empty())
        {
          // a wear pattern is resolved by the triangles: they should stay smaller than a particle
          double      longest = 0;
          const auto &mesh    = wc.wall.mesh;
          for (const auto &t : mesh.triangles)
            for (int k = 0; k < 3; ++k)
              longest = std::max(longest, (mesh.vertices[t[k]] - mesh.vertices[t[(k + 1) % 3]]).norm());
          if (longest > radius)
            c.warnings.push_back("Wall " + name + ": its triangles (edges up to " + io::format_number(longest) +
                                 " m) are larger than the coarse-grained particles (radius " +
                                 io::format_number(radius) +
                                 " m): the wear pattern is resolved only to the triangles (Maximum edge length)");
        }
      if (wc.probe && wc.probe_thickness > 0)
        c.warnings.push_back("Wall " + name + "/Layer probe/Thickness is fixed (" + io::format_number(wc.probe_thickness) +
                             " m) while the particles are coarse-grained: 0 ties it to the simulated radius");
    }
  } // namespace

  void declare_wall_choices(ParameterHandler &prm, const std::vector<std::string> &walls)
  {
    for (const auto &name : walls)
      {
        prm.enter_subsection("Wall " + name);
        const WallChoices defaults = default_wall_choices(name);
        prm.declare_entry("Geometry", defaults.geometry, dealii::Patterns::Anything());
        prm.enter_subsection("Motion");
        prm.declare_entry("Type", defaults.motion, dealii::Patterns::Anything());
        prm.leave_subsection();
        prm.leave_subsection();
      }
  }

  std::map<std::string, WallChoices> read_wall_choices(ParameterHandler &prm, const std::vector<std::string> &walls)
  {
    std::map<std::string, WallChoices> choices;
    for (const auto &name : walls)
      {
        prm.enter_subsection("Wall " + name);
        WallChoices chosen{trim(prm.get("Geometry")), ""};
        prm.enter_subsection("Motion");
        chosen.motion = trim(prm.get("Type"));
        prm.leave_subsection();
        prm.leave_subsection();
        if (make_wall_geometry(chosen.geometry) && dem::make_wall_motion(chosen.motion))
          choices[name] = chosen;
      }
    return choices;
  }

  void declare_wall(ParameterHandler &prm, const std::string &name, const WallChoices *choices)
  {
    prm.enter_subsection("Wall " + name);
    declare_geometry(prm, choices);
    declare_material(prm, 7e10, 0.3, 7800, false);
    declare_interaction(prm, 0.6, wall_defaults(name).friction, "particle-wall");
    declare_wear(prm, name);
    declare_layer_probe(prm, name);
    declare_motion(prm, name, choices);
    prm.leave_subsection();
  }

  DemCase::WallCase read_wall(ParameterFile &f, const std::string &name, DemCase &c)
  {
    const std::vector<std::string> wp = {"Wall " + name};
    f.handler().enter_subsection(wp[0]);
    DemCase::WallCase wc;
    wc.wall.name = name;
    read_geometry(f, wp, c, wc);
    wc.material    = read_material(f, wp, name);
    wc.interaction = read_interaction(f, wp);
    read_wear(f, wp, c, wc);
    read_layer_probe(f, wp, wc);
    warn_of_coarse_graining(name, c, wc);
    read_motion(f, wp, c, wc);
    f.handler().leave_subsection();
    return wc;
  }

  /// Places every mounted part (a grab's knife) on its shell's lip and gives it the shell's motion (one rigid
  /// body with it). The part's frame: x along the length from 0, y across the thickness, z from
  /// the edge up; on the shell: x along the hinge (y; -y on a -x shell), z along the shell's
  /// bottom from the lip inwards, +y towards the shell's inside (the hinge), the edge
  /// 'Protrusion' beyond the lip.
  void mount_parts(ParameterFile &f, DemCase &c, const double length)
  {
    c.mounted_part_length = length;
    for (auto &wc : c.walls)
      {
        if (wc.mount.empty())
          continue;
        const std::vector<std::string> wp = {"Wall " + wc.wall.name};
        auto shell = std::find_if(c.walls.begin(), c.walls.end(), [&](const auto &o) { return o.wall.name == wc.mount; });
        if (shell == c.walls.end() || !shell->lip)
          f.fail(wp, "Mounted on",
                 "'" + wc.mount + "' is not a wall with a lip (in Walls; Geometry = clamshell shell, or a file with 'Lip centre')");
        const Vec3 along = shell->lip->along, up = shell->lip->inward, lip = shell->lip->centre;
        const Vec3 across = up.cross(along);
        wc.rotation.col(0) = along, wc.rotation.col(1) = across, wc.rotation.col(2) = up;
        wc.offset          = lip - wc.protrusion * up - 0.5 * length * along;
        wc.wall.motion     = shell->wall.motion;
        if (wc.wall.motion.kind == dem::WallMotion::Kind::rigid_body)
          {
            if (shell->wall.motion.body.empty())
              shell->wall.motion.body = "shell " + shell->wall.name;
            wc.wall.motion.body    = shell->wall.motion.body;
            wc.wall.motion.mass    = 0; // the shell's mass is the body's
            wc.wall.motion.inertia = Vec3::Zero();
          }
      }
  }

  WallDefaults wall_defaults(const std::string &name)
  {
    if (name == "knife") // the default case's knife
      return {{"box", "prescribed"}, "archard", true, "penetration: 0, 0, -1.5; travel: 1.5, 0, 0", 0.4};
    return {{"box", "fixed"}, "", false, "", 0.5};
  }

  WallChoices default_wall_choices(const std::string &name) { return wall_defaults(name).choices; }

  std::optional<PluginEntry> plugin_entry(const std::vector<std::string> &path, const std::string &key)
  {
    if (path.empty() || path[0].rfind("Wall ", 0) != 0 || path.size() > 2 || (path.size() == 2 && path[1] != "Motion"))
      return std::nullopt;
    // every registered geometry's and motion's entries with their defaults, gathered once (the
    // registries are complete before main): key -> plugin -> default, per family
    using Table = std::map<std::string, std::map<std::string, std::string>>;
    static const std::pair<Table, Table> tables = [] {
      std::pair<Table, Table> t; // geometries', motions'
      for (const auto &g : make_wall_geometries())
        for (const auto &[k, d] : defaults_of(*g))
          t.first[k][g->name()] = d;
      for (const auto &m : dem::make_wall_motions())
        if (m->section().empty())
          for (const auto &[k, d] : defaults_of(*m))
            t.second[k][m->name()] = d;
      return t;
    }();
    const bool   geometry = path.size() == 1;
    const Table &table    = geometry ? tables.first : tables.second;
    const auto   found    = table.find(key);
    if (found == table.end())
      return std::nullopt;
    return PluginEntry{geometry ? "Geometry" : "Motion/Type", found->second};
  }

  std::optional<ForeignEntry> foreign_entry(const DeclarationLists &lists, const std::vector<std::string> &path,
                                            const std::string &key)
  {
    auto entry = plugin_entry(path, key);
    if (!entry)
      return std::nullopt;
    const std::string wall   = path[0].substr(5);
    const auto        chosen = lists.wall_choices.find(wall);
    if (chosen == lists.wall_choices.end())
      return std::nullopt;
    const std::string ours = entry->family == "Geometry" ? chosen->second.geometry : chosen->second.motion;
    if (entry->defaults.count(ours))
      return std::nullopt; // (its own)
    return ForeignEntry{std::move(*entry), wall, ours, key == "Velocities" ? wall_defaults(wall).velocities : ""};
  }

  bool ForeignEntry::at_default(const std::string &value) const
  {
    if (!own_default.empty() && same_value(value, own_default))
      return true;
    for (const auto &[plugin, default_value] : entry.defaults)
      if (same_value(value, default_value))
        return true;
    return false;
  }

  bool same_value(std::string a, std::string b)
  {
    for (auto *s : {&a, &b})
      {
        s->erase(std::remove_if(s->begin(), s->end(), [](unsigned char c) { return std::isspace(c); }), s->end());
        std::transform(s->begin(), s->end(), s->begin(), [](unsigned char c) { return std::tolower(c); });
        if (*s == "yes")
          *s = "true";
        if (*s == "no")
          *s = "false";
      }
    if (a == b)
      return true;
    const auto x = split_string_list(a), y = split_string_list(b);
    if (x.size() != y.size())
      return false;
    try
      {
        for (std::size_t k = 0; k < x.size(); ++k)
          if (std::stod(x[k]) != std::stod(y[k]))
            return false;
        return true;
      }
    catch (const std::exception &)
      {
        return false;
      }
  }

  std::string foreign_entry_hint(const DeclarationLists &lists, const std::vector<std::string> &path,
                                 const std::string &key)
  {
    const auto f = foreign_entry(lists, path, key);
    if (!f)
      return "";
    const std::string &family = f->entry.family, theirs = f->entry.defaults.begin()->first;
    return " '" + key + "' is an entry of " + family + " = " + theirs + ", and wall " + f->wall + "'s " + family +
           " is " + f->ours + ": set " + family + " = " + theirs + ", or leave it out.";
  }

  bool a_wall_is_the_part(ParameterFile &f)
  {
    auto &prm   = f.handler();
    bool  holds = false;
    for (const auto &name : split_string_list(prm.get("Walls")))
      {
        prm.enter_subsection("Wall " + name);
        holds = holds || prm.get("Geometry") == "solid model";
        prm.leave_subsection();
      }
    return holds;
  }
} // namespace abrade::coupling
