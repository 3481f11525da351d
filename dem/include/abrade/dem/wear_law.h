#pragma once
// Wear laws as plugins, in the manner of ASPECT's plugins: a law is one class in one file of
// dem/source/dem/wear_laws/ that says
//
//  - which fields it records per triangle (name, unit, whether the field is a worn volume),
//  - which parameters it takes (declared, read and checked in its own subsection
//    "Wall NAME/Wear/<Law>", through the ParameterSection below, so that the DEM library needs
//    no parameter-file library), and
//  - what one step's wall contacts add to its fields (record()),
//
// and registers itself there with one line,
//
//   ABRADE_REGISTER_WEAR_LAW(Archard);
//
// on the registry every plugin family shares (common/plugin_registry.h). The names a user may
// write in "Wall NAME/Wear/Laws", the subsections `abrade params` documents and the fields the
// outputs carry all come from that registry, so a law's name is spelled once
// (docs/developer-guide.md, "Add a wear law"). The laws are a library of their own, linked
// whole into every program (abrade_dem_program in dem/CMakeLists.txt): nothing names a law's
// file, so a linker would otherwise leave it out.
//
// A law is called once per step with the whole contact log (no virtual call per contact); it
// hands each contact's increments to a WearDeposit, which splits them over the triangles that
// share the contact point and keeps them per phase (WearRecorder, wear.h).
#include <abrade/common/plugin_registry.h>
#include <abrade/dem/contact_log.h>
#include <abrade/dem/parameter_section.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace abrade::dem
{
  class Simulation;

  /// A field a law records per triangle.
  struct WearField
  {
    std::string name; ///< column and VTK field name ("archard_volume")
    std::string unit; ///< "m^3", "J", "m", ...
    std::string doc;
    /// A worn volume [m^3]: outputs also give it as a depth (volume / triangle area, named
    /// depth_name()), and the lifetime loop, sweep, concepts and calibrate can take it.
    bool volume = false;
    /// The law's increments are depths already: each triangle's share is divided by its area.
    bool per_area = false;

    /// "archard_volume" -> "archard_depth" (volume fields only).
    std::string depth_name() const;
  };

  /// What a law may need to know of the run beyond its own parameters.
  struct WearContext
  {
    /// Particles/Coarse graining/Factor: simulated radius = f x real radius (laws with a
    /// particle-size term use the real size).
    double coarse_graining = 1;
  };

  /// Where a law puts one contact's wear: @p field is the index into the law's fields().
  /// Collects only the contacts of one wall (for_each_contact skips the others).
  class WearDeposit
  {
  public:
    virtual ~WearDeposit() = default;
    virtual void add(const WallContactRecord &contact, int field, double amount) = 0;
    /// The wall whose contacts are recorded.
    virtual int wall() const = 0;

    template <typename F>
    void for_each_contact(const ContactLog &log, F &&f)
    {
      const int w = wall();
      log.for_each([&](const WallContactRecord &r) {
        if (r.wall == w)
          f(r);
      });
    }
  };

  class WearLaw
  {
  public:
    virtual ~WearLaw() = default;
    /// The name written in "Wall NAME/Wear/Laws" (lower case, no blanks).
    virtual std::string name() const = 0;
    /// The subsection of its parameters ("Archard"), and its one-paragraph documentation.
    virtual std::string section() const = 0;
    virtual std::string documentation() const = 0;
    virtual std::vector<WearField> fields() const = 0;

    virtual void declare_parameters(ParameterSection &) const {}
    /// Reads (and checks) the parameters of one wall.
    virtual void parse_parameters(const ParameterSection &, const WearContext &) {}

    /// Whether the law uses the real particle size (WearContext::coarse_graining): such a law
    /// cannot be used with a multi-level coarse graining, whose particles have two factors.
    virtual bool uses_particle_size() const { return false; }

    /// The parameter every field is proportional to (Archard's W), which calibration against
    /// measured wear rescales; 0: none. Its entry's name in section().
    virtual double      coefficient() const { return 0; }
    virtual std::string coefficient_name() const { return ""; }

    /// One step's contacts: every contact of @p deposit's wall adds its increments.
    virtual void record(const Simulation &sim, const ContactLog &log, WearDeposit &deposit) const = 0;
  };

  /// The registered laws in the order of their names: one instance each, with default
  /// parameters, to ask for names, fields and documentation.
  const std::vector<std::unique_ptr<WearLaw>> &registered_wear_laws();
  /// The names of the registered laws, "archard, finnie, ..." (@p separator between them).
  std::string wear_law_names(const std::string &separator = ", ");
  /// A new law of that name; an InputError naming the allowed names if there is none.
  std::unique_ptr<WearLaw> make_wear_law(const std::string &name);
  /// A new law of that name with its parameters' defaults, except those in @p values (entry
  /// name -> value; an unknown entry is an InputError): for programs and tests that set a law
  /// up without a parameter file.
  std::unique_ptr<WearLaw> make_wear_law(const std::string &name, const std::map<std::string, double> &values,
                                         const WearContext &context = {});
  /// The law that records field @p field (nullptr: none).
  const WearLaw *wear_law_of_field(const std::string &field);

  /// Adds a law (ABRADE_REGISTER_WEAR_LAW); a name registered twice is a bug.
  struct WearLawRegistration
  {
    explicit WearLawRegistration(std::unique_ptr<WearLaw> (*make)());
  };
} // namespace abrade::dem

/// One line in a law's file registers it (at namespace scope).
#define ABRADE_REGISTER_WEAR_LAW(Class)                                                                    \
  ABRADE_REGISTER_PLUGIN(::abrade::dem::WearLawRegistration, ::abrade::dem::WearLaw, Class)
