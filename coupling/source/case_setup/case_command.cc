// `abrade case`: a lifetime case written around a user's part (case_command.h).
//
// 1. Read the part as the case will (File scale; Part/Place = lowest point at z = 0, centred)
//    on a coarse mesh: its bounding box, volume and surface; its plate thickness about
//    2 volume / surface (a plate's two faces).
// 2. Size the drag: the part comes down quickly (4 m/s) from its start above the poured
//    particles to just above the bed, goes down into the bed by half its height (--depth), then
//    along x twice its length, at least a metre (--travel), at 1.5 m/s (--speed). The bed is that deep
//    plus a quarter of the part's height below (at least 0.1 m), its box the path with a margin
//    of a quarter of the part (at least 0.15 m) on every side.
// 3. Size the particles: the preset's real radius, coarse-grained (Particles/Coarse graining) so
//    that the settled bed holds about --particles of them; poured from a region below the part's
//    start at a solid fraction of 0.3 (the bed check refuses more than 0.37) and settled for
//    the time a particle takes to fall the region's height, and 0.3 s more.
// 4. Write the .prm, every number with where it came from, and read it back as a run would (the
//    bed's fill, the memory and run-size checks).
#include <abrade/common/error.h>
#include <abrade/common/finite_number.h>
#include <abrade/common/format_number.h>
#include <abrade/coupling/case_setup/case_command.h>
#include <abrade/coupling/parameters/parameter_file.h>
#include <abrade/coupling/parameters/parameters.h>
#include <abrade/fem/solid_output.h>
#include <abrade/fem/part_faces.h>
#include <abrade/fem/solid_file.h>
#include <abrade/fem/solid_surface.h>

#include <deal.II/grid/grid_tools.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>

namespace abrade::coupling
{
  namespace
  {
    const char *case_usage = R"(usage:
  abrade case PART --output FILE.prm [--material iron-ore-pellets|gravel|coal|soil]
              [--clamped "SELECTORS"] [--wearable "SELECTORS"] [--file-scale S]
              [--depth D] [--travel L] [--speed V] [--particles N] [--beds N] [--updates N]
      write a lifetime case around PART (STEP/IGES, STL, .msh): the part dragged through a bed
      of the material, down into it by D (default half the part's height) and along x by L
      (default twice its length, at least 1 m) at V m/s (1.5); the bed, container, domain,
      particle size (coarse-grained to about N particles, default 15000), settling, phases and
      tonnes per cycle chosen from the part; N beds (seeds, default 3) per update, at most N
      updates (default 20). Selectors as Part/Clamped faces takes them (abrade preview shows
      the faces).)";

    /// A bulk material: its particles and their contacts (the knife-bed's pellets as the thesis
    /// measured them; the others from handbook values, to be calibrated like W).
    struct Material
    {
      const char *name;
      double      density;        ///< [kg/m^3] of a particle
      double      radius;         ///< [m] of a real particle
      double      restitution, friction, wall_friction;
      double      solid_fraction; ///< of the settled bed
      const char *source;
    };
    const Material materials[] = {
      {"iron-ore-pellets", 3700, 0.0069, 0.6, 0.5, 0.4, 0.6,
       "the thesis' pellets (the knife-bed case): 13.8 mm, 3700 kg/m^3, restitution 0.6, friction 0.5"},
      {"gravel", 2650, 0.01, 0.4, 0.6, 0.5, 0.6, "crushed gravel, 20 mm: handbook values, to be calibrated"},
      {"coal", 1350, 0.01, 0.3, 0.5, 0.4, 0.55, "lump coal, 20 mm: handbook values, to be calibrated"},
      {"soil", 2600, 0.002, 0.2, 0.6, 0.5, 0.6,
       "soil as 4 mm grains without cohesion: coarse-grained heavily; handbook values, to be calibrated"}};

    struct Options
    {
      std::string part, output, material = "iron-ore-pellets", clamped, wearable;
      double      file_scale = 1, depth = 0, travel = 0, speed = 1.5;
      long        particles = 15000, beds = 3, updates = 20;
    };

    double positive(const std::string &flag, const std::string &text)
    {
      const auto v = io::finite_number(text);
      if (!v || !(*v > 0))
        throw InputError("command line", flag + ": a positive number expected, got '" + text + "'");
      return *v;
    }

    Options parse(const std::vector<std::string> &args)
    {
      Options o;
      for (std::size_t k = 0; k < args.size(); ++k)
        {
          const std::string &a     = args[k];
          auto               value = [&]() -> std::string {
            if (k + 1 >= args.size())
              throw InputError("command line", a + " needs a value\n" + case_usage);
            return args[++k];
          };
          if (a == "--output" || a == "-o")
            o.output = value();
          else if (a == "--material")
            o.material = value();
          else if (a == "--clamped")
            o.clamped = value();
          else if (a == "--wearable")
            o.wearable = value();
          else if (a == "--file-scale")
            o.file_scale = positive(a, value());
          else if (a == "--depth")
            o.depth = positive(a, value());
          else if (a == "--travel")
            o.travel = positive(a, value());
          else if (a == "--speed")
            o.speed = positive(a, value());
          else if (a == "--particles" || a == "--beds" || a == "--updates")
            {
              const double v = positive(a, value());
              if (v != std::floor(v) || v > 1e7)
                throw InputError("command line", a + ": a whole number expected");
              (a == "--particles" ? o.particles : a == "--beds" ? o.beds : o.updates) = long(v);
            }
          else if (!a.empty() && a[0] == '-')
            throw InputError("command line", "unknown option '" + a + "'\n" + case_usage);
          else if (o.part.empty())
            o.part = a;
          else
            throw InputError("command line", "one part only ('" + o.part + "', then '" + a + "')\n" + case_usage);
        }
      if (o.part.empty() || o.output.empty())
        throw InputError("command line", "case needs a part and --output FILE.prm\n" + std::string(case_usage));
      if (std::filesystem::path(o.output).extension() != ".prm")
        throw InputError("command line", "--output names the parameter file to write (FILE.prm), got '" + o.output + "'");
      if (std::filesystem::exists(o.output))
        throw InputError(o.output, "exists: abrade case does not overwrite a parameter file; remove it or name another");
      if (o.particles < 500)
        throw InputError("command line", "--particles: at least 500 (a bed of fewer is not a bed)");
      return o;
    }

    /// What the case needs of the part, placed as the case places it.
    struct PartShape
    {
      std::array<double, 3> extent{}; ///< [m] of its bounding box (its lowest point at z = 0, centred)
      double                volume = 0, area = 0;
      /// [m] the surface point furthest along x (the leading edge as it is dragged along +x; of
      /// those within a millimetre, the lowest, then the nearest y = 0) and the lowest point (of
      /// those within a millimetre, the furthest along x, then the nearest y = 0)
      dealii::Point<3> leading, lowest;
    };

    using P = dealii::Point<3>;

    /// The point of @p points with the largest first key; of those within a millimetre of it,
    /// the one with the largest second key, and so on; of those left, one on the +y side, then
    /// the first in the order of their coordinates. The points' order does not decide (along
    /// a straight bottom edge every vertex is as low as the next: comparing one point after
    /// another would take whichever the mesh lists first), nor does round-off between mirror
    /// images; a point at a millimetre band's edge can still go either way by round-off.
    P extreme(const std::vector<P> &points, const std::vector<std::function<double(const P &)>> &keys)
    {
      std::vector<P> left = points;
      for (const auto &key : keys)
        {
          double best = -std::numeric_limits<double>::infinity();
          for (const P &p : left)
            best = std::max(best, key(p));
          left.erase(std::remove_if(left.begin(), left.end(), [&](const P &p) { return key(p) < best - 1e-3; }),
                     left.end());
        }
      return *std::min_element(left.begin(), left.end(), [](const P &a, const P &b) {
        if ((a[1] >= 0) != (b[1] >= 0))
          return a[1] >= 0;
        return std::lexicographical_compare(a.begin_raw(), a.end_raw(), b.begin_raw(), b.end_raw());
      });
    }

    PartShape measure_part(const std::string &path, double file_scale)
    {
      fem::SolidFileSettings s;
      s.scale = file_scale;
      fem::parse_part_placement("lowest point at z = 0, centred", s);
      // a coarse mesh first, for the size; then one of a tenth of the part's smallest extent
      // (a plate's thickness is what the mesh must resolve for its volume and surface)
      PartShape shape;
      for (double h : {0.1, 0.0})
        {
          if (h == 0)
            h = std::clamp(*std::min_element(shape.extent.begin(), shape.extent.end()) / 3,
                           0.002, 0.1 * *std::max_element(shape.extent.begin(), shape.extent.end()));
          dealii::Triangulation<3> tria;
          fem::read_solid(path, h, tria, s);
          const dealii::BoundingBox<3> box = dealii::GridTools::compute_bounding_box(tria);
          for (int d = 0; d < 3; ++d)
            shape.extent[d] = box.upper_bound(d) - box.lower_bound(d);
          shape.volume                    = fem::mesh_volume(tria);
          const fem::SolidSurface surface = fem::extract_surface(tria);
          shape.area                      = surface.area();
          shape.leading = extreme(surface.vertices, {[](const P &p) { return p[0]; }, [](const P &p) { return -p[2]; },
                                                     [](const P &p) { return -std::abs(p[1]); }});
          shape.lowest  = extreme(surface.vertices, {[](const P &p) { return -p[2]; }, [](const P &p) { return p[0]; },
                                                     [](const P &p) { return -std::abs(p[1]); }});
        }
      return shape;
    }

    std::string vec(double x, double y, double z)
    {
      return io::format_number(x, 5) + ", " + io::format_number(y, 5) + ", " + io::format_number(z, 5);
    }

    /// The material of --material (refused with the list of them).
    const Material &material_named(const std::string &name)
    {
      const auto m = std::find_if(std::begin(materials), std::end(materials), [&](const Material &x) { return name == x.name; });
      if (m == std::end(materials))
        throw InputError("command line", "--material: iron-ore-pellets, gravel, coal or soil, got '" + name + "'");
      return *m;
    }

    /// The drag and the bed around a part: the knife-bed's, scaled to the part.
    struct Drag
    {
      Drag(const PartShape &part, const Options &o, const Material &m)
      {
        const double lx = part.extent[0], ly = part.extent[1], lz = part.extent[2];
        thickness = part.area > 0 ? 2 * part.volume / part.area : 0.1 * lz;
        // the drag: down half the part's height, along x twice its length
        depth               = o.depth > 0 ? o.depth : 0.5 * lz;
        travel              = o.travel > 0 ? o.travel : std::max(2 * lx, 1.0);
        const double below  = std::max(0.25 * lz, 0.1);
        bed                 = depth + below; // the settled bed's height
        const double margin = std::max(0.25 * std::max(lx, ly), 0.15);
        length = lx + travel + 2 * margin, width = ly + 2 * margin;
        x_min = -0.5 * length, y_min = -0.5 * width;
        // the particles: coarse-grained to about the count asked; poured from below the part
        const double settled_solid = m.solid_fraction * length * width * bed; // [m^3]
        const double r_sim = std::cbrt(settled_solid / (double(o.particles) * 4.0 / 3.0 * M_PI));
        factor             = std::max(1.0, std::ceil(10 * r_sim / m.radius) / 10); // (one decimal)
        r                  = factor * m.radius;                                   // simulated radius
        pour               = bed * m.solid_fraction / pour_fraction;               // the region's height
        region_low = 2 * r, region_high = region_low + pour;
        start_z        = region_high + 2 * r; // the part's lowest point
        top            = start_z + lz + std::max(0.1, 4 * r);
        settle         = std::sqrt(2 * pour / 9.81) + 0.3;
        surface        = bed + 2 * r + 0.05; // the approach ends above the bed, at speed
        approach_speed = std::max(4.0, o.speed);
        start_x        = x_min + margin + 0.5 * lx;
        bulk           = m.solid_fraction * m.density;        // [kg/m^3]
        tonnes         = 1e-3 * bulk * ly * depth * travel; // the swept volume's
        limit          = std::max(0.002, 0.5 * thickness);
      }
      static constexpr double pour_fraction = 0.3;
      double thickness, depth, travel, bed, length, width, x_min, y_min, factor, r, pour, region_low, region_high,
        start_z, top, settle, surface, approach_speed, start_x, bulk, tonnes, limit;
    };

    /// The part by a relative name when it lies beside the case file or below it (the two move
    /// together); else by its absolute name.
    std::string part_path_from(const Options &o)
    {
      std::string part_path = std::filesystem::absolute(o.part).lexically_normal().string();
      const auto  dir       = std::filesystem::absolute(std::filesystem::path(o.output)).parent_path();
      const auto  rel       = std::filesystem::absolute(o.part).lexically_normal().lexically_relative(dir);
      if (!rel.empty() && rel.begin()->string() != "..")
        part_path = rel.string();
      return part_path;
    }

    /// A number as a case file writes it (4 significant digits unless said).
    std::string num(double x, int digits = 4) { return io::format_number(x, digits); }

    /// The case file's opening comment: what wrote it, the part, its drag, what is left to set.
    void write_case_heading(std::ostream &f, const std::vector<std::string> &args, const Options &o,
                            const PartShape &part, const Drag &d)
    {
      auto n = [](double x, int digits = 4) { return num(x, digits); };
      const double lx = part.extent[0], ly = part.extent[1], lz = part.extent[2];
      f << "# A lifetime case around " << o.part << ", written by abrade case:\n#   abrade case";
      for (const auto &a : args)
        f << ' ' << (a.find(' ') != std::string::npos ? "\"" + a + "\"" : a);
      f << "\n#\n# The part (placed: its lowest point at z = 0, the bounding box centred): " << n(lx, 4) << " x " << n(ly, 4)
        << " x " << n(lz, 4) << " m, " << n(part.volume, 4) << " m^3, surface " << n(part.area, 4)
        << " m^2, plate thickness about 2 V / A = " << n(1000 * d.thickness, 3) << " mm.\n"
        << "# It is dragged as the knife-bed drags its knife: down into the bed by " << n(d.depth, 3)
        << " m, then along +x by " << n(d.travel, 3) << " m, at " << n(o.speed, 3) << " m/s.\n"
        << "# What it cannot know, set before a life is booked: which faces are clamped (Part/Clamped\n"
        << "# faces), the end of life (Lifetime/Maximum depth, ...), W (calibrate it: abrade calibrate), the\n"
        << "# tonnes per cycle if a payload is measured. See it first:\n"
        << "#   abrade preview " << o.output << " --output preview\n# then run it:\n#   abrade run " << o.output
        << "\nset Job   = lifetime\nset Walls = container, part\n\n";
    }

    /// Output and Simulation: the domain around the container, the phases of the drag.
    void write_case_simulation(std::ostream &f, const Options &o, const Drag &d)
    {
      auto n = [](double x, int digits = 4) { return num(x, digits); };
      f << "subsection Output\n  set Directory         = output-" << std::filesystem::path(o.part).stem().string()
        << "\n  set Snapshot interval = 0\n  set Write particles   = false\nend\n\n"
        << "subsection Simulation\n"
        << "  # the container and " << n(0.05, 2) << " m around it\n"
        << "  set Domain min = " << vec(d.x_min - 0.05, d.y_min - 0.05, -0.05) << "\n"
        << "  set Domain max = " << vec(-d.x_min + 0.05, -d.y_min + 0.05, d.top + 0.05) << "\n"
        << "  # from its start above the poured particles quickly down to " << n(d.surface, 3) << " m (approach), then\n"
        << "  # " << n(d.depth, 3) << " m into the bed (its surface at about " << n(d.bed, 3) << " m; penetration), then along x (travel)\n"
        << "  set Phases     = approach: " << n((d.start_z - d.surface) / d.approach_speed, 5)
        << ", penetration: " << n((d.surface - (d.bed - d.depth)) / o.speed, 5) << ", travel: " << n(d.travel / o.speed, 5) << "\n"
        << "  set Characteristic velocity = " << n(o.speed, 3) << "\n"
        << "  # (the knife-bed's: the pour's impacts of coarse-grained particles reach 30 % of a radius; such\n"
        << "  # overlaps are counted per update in trajectory.csv and warned about, not fatal)\n"
        << "  set Maximum overlap fraction = 0.3\n  set On error = continue\n"
        << "  set Threads    = 0\nend\n\n";
    }

    /// Particles: the material, its pour, its coarse graining, its settling.
    void write_case_particles(std::ostream &f, const Options &o, const Drag &d, const Material &m)
    {
      auto n = [](double x, int digits = 4) { return num(x, digits); };
      f << "subsection Particles\n"
        << "  # " << m.source << "\n"
        << "  subsection Material\n    set Density         = " << n(m.density, 4) << "\n"
        << "    set Shear modulus   = 1e8\n    set Poisson's ratio = 0.25\n"
        << "    # rotation-locked spheres stand in for the grains' interlocking (the thesis' choice)\n"
        << "    set Rotation        = false\n  end\n"
        << "  subsection Interaction\n    set Restitution = " << n(m.restitution, 3) << "\n    set Friction    = "
        << n(m.friction, 3) << "\n  end\n"
        << "  subsection Generation\n"
        << "    # poured from below the part's start at a solid fraction of 0.3; the bed settles to about "
        << n(d.bed, 3) << " m\n"
        << "    set Region min       = " << vec(d.x_min + 2 * d.r, d.y_min + 2 * d.r, d.region_low) << "\n"
        << "    set Region max       = " << vec(-d.x_min - 2 * d.r, -d.y_min - 2 * d.r, d.region_high) << "\n"
        << "    set Radius           = " << n(m.radius, 4) << "\n"
        << "    set Solid fraction   = " << n(d.pour_fraction, 2) << "\n"
        << "    set Initial velocity = 0, 0, -0.5\n  end\n"
        << "  subsection Coarse graining\n"
        << "    # the real " << n(1000 * m.radius, 3) << " mm radius times " << n(d.factor, 3)
        << ": about " << o.particles << " particles in the bed (docs/coarse-graining.md: W holds for the\n"
        << "    # size it was fitted at)\n    set Factor = " << n(d.factor, 3) << "\n  end\n"
        << "  subsection Settling\n    # a fall through the pour region's height and 0.3 s\n"
        << "    set Kinetic energy threshold = 0\n    set Maximum time             = " << n(d.settle, 3) << "\n  end\nend\n\n";
    }

    /// The walls: the container, and the part with its wear law and its drag.
    void write_case_walls(std::ostream &f, const Options &o, const Drag &d, const Material &m)
    {
      auto n = [](double x, int digits = 4) { return num(x, digits); };
      f << "subsection Wall container\n  set Geometry = box\n"
        << "  set Box min  = " << vec(d.x_min, d.y_min, 0) << "\n  set Box max  = " << vec(-d.x_min, -d.y_min, d.top) << "\n"
        << "  subsection Interaction\n    set Restitution = " << n(m.restitution, 3) << "\n    set Friction    = "
        << n(m.friction, 3) << "\n  end\nend\n\n"
        << "subsection Wall part\n  # the part (subsection Part) placed at its start, above the bed\n"
        << "  set Geometry = solid model\n  set Offset   = " << vec(d.start_x, 0, d.start_z) << "\n"
        << "  subsection Interaction\n    set Restitution = " << n(m.restitution, 3) << "\n    set Friction    = "
        << n(m.wall_friction, 3) << "\n  end\n"
        << "  subsection Wear\n    set Laws = archard\n    subsection Archard\n"
        << "      # the knife-bed's W for steel in iron-ore pellets: calibrate it (abrade calibrate)\n"
        << "      set Coefficient = 2e-14\n    end\n  end\n"
        << "  subsection Motion\n    set Type       = prescribed\n"
        << "    set Velocities = approach: 0, 0, " << n(-d.approach_speed, 3) << "; penetration: 0, 0, " << n(-o.speed, 3)
        << "; travel: " << n(o.speed, 3) << ", 0, 0\n"
        << "  end\nend\n\n";
    }

    /// Part: the part's file, its placing, mesh size and faces.
    void write_case_part(std::ostream &f, const Options &o, const PartShape &part, const Drag &d)
    {
      auto n = [](double x, int digits = 4) { return num(x, digits); };
      const double lx = part.extent[0], ly = part.extent[1], lz = part.extent[2];
      f << "subsection Part\n  set Geometry  = file\n  set File      = " << part_path_from(o) << "\n";
      if (o.file_scale != 1)
        f << "  set File scale = " << n(o.file_scale, 6) << "\n";
      f << "  set Place     = lowest point at z = 0, centred\n"
        << "  # about the plate thickness, at most a tenth of the part (the knife-bed's: 20 mm for 30 mm)\n"
        << "  set Mesh size = " << n(std::clamp(d.thickness, 0.002, 0.1 * std::max({lx, ly, lz})), 2) << "\n"
        << "  # the faces bolted or welded on (none: every face wears); abrade preview shows them\n"
        << "  set Clamped faces  = " << o.clamped << "\n  set Wearable faces = " << o.wearable << "\nend\n\n";
    }

    /// Lifetime: tonnes per cycle from the swept volume, beds, a first end of life, what to follow.
    void write_case_lifetime(std::ostream &f, const Options &o, const PartShape &part, const Drag &d)
    {
      auto n = [](double x, int digits = 4) { return num(x, digits); };
      const double ly = part.extent[1];
      f << "subsection Lifetime\n"
        << "  # the swept volume (the part's width x its depth in the bed x the travel, " << n(ly, 3) << " x "
        << n(d.depth, 3) << " x " << n(d.travel, 3) << " m)\n  # x the bulk density (" << n(d.bulk, 4)
        << " kg/m^3): no payload measured; a measured one replaces it\n"
        << "  set Tonnes per cycle = " << n(d.tonnes, 4) << "\n"
        << "  set Seeds            = ";
      for (long b = 1; b <= o.beds; ++b)
        f << (b > 1 ? ", " : "") << b;
      f << "\n  # the end of life: half the plate thickness worn, a first guess: set the part's wear limit\n"
        << "  set Maximum depth    = " << n(d.limit, 3) << "\n"
        << "  set Maximum updates  = " << o.updates << "\n"
        << "  # the recession the trajectory follows (point_recession, point_recession_2): the part's leading\n"
        << "  # point (the furthest along x) and its lowest, in the part's frame after Part/Place\n"
        << "  set Recession points = " << vec(part.leading[0], part.leading[1], part.leading[2]);
      if (part.leading.distance(part.lowest) > 0.01)
        f << "; " << vec(part.lowest[0], part.lowest[1], part.lowest[2]);
      f << "\n  # cross-sections at a quarter, the middle and three quarters of the part's length (x)\n"
        << "  set Profile planes   = 0.25, 0.5, 0.75\nend\n";
    }

    /// The lifetime case's parameter file, commented for the user who will finish it.
    std::string case_text(const std::vector<std::string> &args, const Options &o, const PartShape &part,
                          const Drag &d, const Material &m)
    {
      std::ostringstream f;
      write_case_heading(f, args, o, part, d);
      write_case_simulation(f, o, d);
      write_case_particles(f, o, d, m);
      write_case_walls(f, o, d, m);
      write_case_part(f, o, part, d);
      write_case_lifetime(f, o, part, d);
      return f.str();
    }

    /// @p text as @p path, written whole or not at all, then read back as a run reads it: its
    /// bed checked (fill, memory, run size) before anything runs (a refused file is removed).
    void write_and_check(const std::string &path, const std::string &text)
    {
      {
        const std::string tmp = path + ".writing";
        std::ofstream     file(tmp);
        file << text;
        file.close();
        if (!file)
          throw InputError(path, "could not be written");
        std::filesystem::rename(tmp, path);
      }
      try
        {
          ParameterFile check(path, {});
          read_dem_case(check);
        }
      catch (...)
        {
          std::error_code ec;
          std::filesystem::remove(path, ec);
          throw;
        }
    }
  } // namespace

  int run_case_command(const std::vector<std::string> &args)
  {
    const Options   o = parse(args);
    const Material &m = material_named(o.material);
    // (the selectors as a run would take them: an error now, not after the bed)
    try
      {
        fem::parse_face_selectors(o.clamped), fem::parse_face_selectors(o.wearable);
      }
    catch (const std::invalid_argument &e)
      {
        throw InputError("command line", std::string("--clamped / --wearable: ") + e.what());
      }

    std::error_code ec;
    if (!std::filesystem::is_regular_file(o.part, ec))
      throw InputError(o.part, "no such file");
    std::cout << "abrade case: reading " << o.part << " (meshed twice, coarsely)" << std::endl;
    const PartShape part = measure_part(o.part, o.file_scale);
    const Drag      drag(part, o, m);
    write_and_check(o.output, case_text(args, o, part, drag, m));
    std::printf("abrade case: %s written: the part %.3g x %.3g x %.3g m dragged %.3g m through a %.3g x %.3g x %.3g m "
                "bed of %s (%.1f mm particles coarse-grained %.3gx, about %ld), %.4g t a cycle (the swept volume; "
                "no payload measured)\n  next: abrade preview %s --output preview\n",
                o.output.c_str(), part.extent[0], part.extent[1], part.extent[2], drag.travel, drag.length, drag.width,
                drag.bed, m.name, 1000 * m.radius, drag.factor, o.particles, drag.tonnes, o.output.c_str());
    return 0;
  }
} // namespace abrade::coupling
