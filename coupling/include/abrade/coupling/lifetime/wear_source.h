#pragma once
// Where a lifetime update's wear comes from (Lifetime/Wear source, a registered choice): the
// DEM's operating cycle on the part's current surface, a DEM run's stored wear, or a known
// analytic rate (verification). The loop asks for one
// cycle's wear per bed seed, as a wear volume at every vertex of the part's surface: deposited
// where the contacts happened (barycentric weights of each contact point, dem/wear.h), so that
// wear at the chisel's tip stays on the tip's vertices.
#include <abrade/common/plugin_registry.h>
#include <abrade/coupling/jobs.h>
#include <abrade/coupling/parameters/parameters.h>
#include <abrade/fem/solid_surface.h>

#include <deal.II/base/parameter_handler.h>

#include <memory>
#include <string>
#include <vector>

namespace abrade::coupling::lifetime
{
  /// One operating cycle's wear on the part.
  struct CycleWear
  {
    std::vector<std::vector<double>> seed_volume;   ///< per seed: wear volume per cycle at each surface vertex [m^3]
    std::vector<double>              phase_volume;  ///< the seeds' mean, per phase of the cycle [m^3]
    double                           tonnes_per_cycle = 0;
    double                           particle_radius  = 0; ///< the largest particle's [m] (0: no particles)
    std::string                      stop; ///< not empty: why the loop cannot go on (no payload, ...)
    /// the beds of seed_volume when the source chose them itself (a replay: the stored run's);
    /// empty: the beds the loop asked for
    std::vector<int> bed_seeds;
    /// the source's warnings of the cycle (the DEM's overlaps, lost particles, time step, per
    /// seed; a replay beyond its stored run): the loop logs and counts them
    std::vector<std::string> warnings;
    /// warnings about the run's set-up rather than a fault of the cycle (a saved bed that another
    /// case made): the loop logs each text once and lists it in summary.json, not counting it
    std::vector<std::string> notes;
  };

  /// The bed seed of base seed @p seed in @p update (1-based; 0: the pilot cycle that sizes the
  /// first update), round @p round (extra beds of a target interval): the seed itself in update
  /// 1, round 0 (a case's settled beds stay valid); otherwise a 30-bit mix of the three
  /// (SplitMix64) plus one, the same on every machine.
  int bed_seed(int seed, long update, long round = 0);

  class WearSource
  {
  public:
    virtual ~WearSource() = default;
    /// The wear of one cycle on the part's current @p surface (its vertex order), after
    /// @p tonnes handled so far, on one bed per seed of @p bed_seeds.
    virtual CycleWear cycle(const fem::SolidSurface &surface, double tonnes, const std::vector<int> &bed_seeds) = 0;
    /// The phases of the cycle (trajectory columns FIELD_<phase>: archard_volume_penetration).
    virtual std::vector<std::string> phases() const = 0;
    /// The coefficient the wear scales with (the part's law of Output/Wear field: Archard's W;
    /// 0: none, or not the DEM's).
    virtual double wear_coefficient() const { return 0; }
    /// Whether the wear is a volume of material removed (Archard's law measures one): the
    /// loop then has the moved part lose exactly that volume in every update
    /// (PartModel::apply_wear). A known depth rate (verification) is not.
    virtual bool removes_volume() const { return true; }
    /// What the wear comes from, in the loop's messages.
    virtual std::string name() const { return "DEM"; }
  };

  /// What a wear source is made from at the lifetime loop's set-up.
  struct WearSourceSetUp
  {
    JobContext              &ctx;
    const DemCase           &dem_case;
    const std::vector<int>  &seeds;            ///< Lifetime/Seeds
    double                   tonnes_per_cycle; ///< Lifetime/Tonnes per cycle (0: the DEM's payload)
    const fem::SolidSurface &design;           ///< the part's design surface
    double                   mesh_size;        ///< Part/Mesh size [m]
  };

  /// A choice of Lifetime/Wear source, as a plugin: a class in a file of its own in
  /// coupling/source/lifetime/wear_sources/ that declares, reads and checks its own entries (in
  /// its subsection of Lifetime, section()) and makes the WearSource the loop draws every cycle's wear from;
  /// registered there with one line, ABRADE_REGISTER_WEAR_SOURCE(Class). Its library is linked
  /// whole into the programs (abrade_program), which is what makes a registration in a file
  /// nothing names reach them.
  class WearSourceChoice
  {
  public:
    virtual ~WearSourceChoice() = default;
    /// The name written in Lifetime/Wear source ("dem").
    virtual std::string name() const = 0;
    /// What it does, a sentence for Wear source's documentation.
    virtual std::string documentation() const = 0;
    /// Whether its wear comes from particles (the DEM's, or stored by a DEM run): the part is
    /// then a solid-model wall whose wear laws record Output/Wear field, its W can be calibrated
    /// and the wear filter's length defaults to the particle radius. Otherwise a known rate.
    virtual bool from_particles() const = 0;
    /// The subsection of Lifetime its entries are in ("Analytic": Lifetime/Analytic/Wear rate).
    virtual std::string section() const = 0;
    /// That subsection's path, for refusals: {"Lifetime", section()}.
    std::vector<std::string> path() const { return {"Lifetime", section()}; }
    /// Declares its entries (in its subsection, which the caller has entered).
    virtual void declare_parameters(dealii::ParameterHandler &) const {}
    /// Reads and checks them (in its subsection, entered); refusals through file.fail(path(), ...).
    virtual void parse_parameters(ParameterFile &) {}
    /// The source (refusals through ctx.parameters.fail()).
    virtual std::unique_ptr<WearSource> make(const WearSourceSetUp &set_up) const = 0;
    /// The entry a cycle's std::domain_error is about (a rate that is negative somewhere), its
    /// path and key: Lifetime/Wear source unless the source names one of its own.
    virtual std::vector<std::string> rate_entry() const { return {"Lifetime", "Wear source"}; }
    /// Refuses rate_entry() in @p file: @p why.
    [[noreturn]] void fail_on_rate(ParameterFile &file, const std::string &why) const
    {
      const auto entry = rate_entry();
      file.fail({entry.begin(), entry.end() - 1}, entry.back(), why);
    }
    /// Where the wear comes from, for the log ("the DEM").
    virtual std::string description() const = 0;
    /// What it adds to summary.json's results.lifetime.
    virtual void add_results(io::Json &) const {}
  };

  using WearSourceFactory = std::unique_ptr<WearSourceChoice> (*)();
  /// The registered wear sources, one new instance each, in the order of their names.
  std::vector<std::unique_ptr<WearSourceChoice>> make_wear_source_choices();
  /// A new one of that name; nullptr if there is none.
  std::unique_ptr<WearSourceChoice> make_wear_source_choice(const std::string &name);
  /// Declares Lifetime/Wear source and every registered source's entries, each in its
  /// subsection (in Lifetime, entered).
  void declare_wear_sources(dealii::ParameterHandler &prm);
  /// Adds a wear source (ABRADE_REGISTER_WEAR_SOURCE); a name registered twice is a bug.
  struct WearSourceRegistration
  {
    explicit WearSourceRegistration(WearSourceFactory make);
  };

  /// The coefficient of the part's law of Output/Wear field in case @p c (Archard's W; 0: none).
  double case_wear_coefficient(const DemCase &c);

  /// A known wear rate: @p expression, depth per tonne [m/t] as a function of x, y, z [m] (the
  /// current surface) and t (the tonnes handled so far), at every vertex of the wearable
  /// surface; times the tonnes per cycle and the vertex's area (a third of its wearable
  /// triangles'). With @p seed_scatter > 0 each bed's rate is multiplied by a lognormal factor
  /// of mean 1 and relative standard deviation @p seed_scatter, exp(sigma z - sigma^2 / 2) with
  /// sigma^2 = ln(1 + scatter^2) and z a standard normal number drawn from the bed's seed (a
  /// known bed-to-bed scatter, to test the interval). Throws std::invalid_argument when the
  /// expression cannot be evaluated. @p as_volume: rate x tonnes x area is a volume removed
  /// (WearSource::removes_volume), as the DEM's wear is; else the depth itself.
  std::unique_ptr<WearSource> make_analytic_wear_source(const std::string &expression, double tonnes_per_cycle,
                                                        double seed_scatter, bool as_volume = false);

  /// The DEM: one cycle per bed seed from that seed's settled bed (beds/bed-seedN.bed in the
  /// output directory, settled on first use; the beds of derived seeds are deleted after their
  /// cycle), on every knife wall (a grab's two knives are averaged vertex by vertex).
  /// @p tonnes_per_cycle 0: the DEM's payload (Simulation/Payload height). Under mpirun the
  /// beds run side by side on groups of about @p ranks_per_bed ranks (0: the ranks shared out
  /// among the beds; dem/ensemble.h), each bed's wear the same as on that many ranks alone.
  std::unique_ptr<WearSource> make_dem_wear_source(const DemCase &c, const std::vector<int> &base_seeds,
                                                   double tonnes_per_cycle, int ranks_per_bed, JobContext &ctx);

  /// The standard normal number that seed @p seed draws (Box-Muller on a 64-bit Mersenne
  /// twister: the same on every platform).
  double standard_normal_of_seed(int seed);
} // namespace abrade::coupling::lifetime

/// One line in a wear source's file registers it (at namespace scope).
#define ABRADE_REGISTER_WEAR_SOURCE(Class)                                                             \
  ABRADE_REGISTER_PLUGIN(::abrade::coupling::lifetime::WearSourceRegistration,                         \
                         ::abrade::coupling::lifetime::WearSourceChoice, Class)
