#pragma once
// End-of-life criteria as plugins. A criterion is a quantity of the worn part that grows with
// the handled tonnes (the largest wear depth below the design, a gauged edge's recession, the
// worn mass, ...) and the limit at which the part is replaced. Each is a class in a file of its
// own in coupling/source/lifetime/criteria/ that declares, reads and checks its own parameters
// (in subsection Lifetime) and registers itself there with one line:
//
//   ABRADE_REGISTER_END_OF_LIFE_CRITERION(MaximumDepth);
//
// The lifetime loop (lifetime_loop.h) keeps every registered criterion's quantity after each
// update, whether its limit is set or not (trajectory.csv and the summary read some of them):
//
//  - value(): the quantity itself, the trajectory end_of_life() crosses (end_of_life.h);
//  - bed_rates(): each bed's rate of it at the place that will end the life, the update's
//    record life_interval() turns into the life's interval (life_interval.h);
//  - places(): the quantity at every place it is read and the beds' rates there, for the worst
//    of many places (place_scatter.h);
//
// and at the end asks the one that ended the life where that was and what the figures draw.
// A criterion whose limit is 0 ends no life.
//
// A criterion reads the part through PartNow (the solid model, the followed points, the
// gauges' sections) and the beds' rates through BedRates, both filled by the loop; it keeps no
// state between updates (a resumed run rebuilds none).
#include <abrade/common/plugin_registry.h>
#include <abrade/coupling/lifetime/edge_gauge.h>
#include <abrade/coupling/lifetime/lifetime_outputs.h>
#include <abrade/coupling/lifetime/wear_rates.h>
#include <abrade/fem/part_model.h>

#include <deal.II/base/parameter_handler.h>

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace abrade::coupling::lifetime
{
  /// The part as the loop measured it after an update (or the design, at the start).
  struct PartNow
  {
    const fem::PartModel               &part;
    const std::vector<dealii::Point<3>> &followed_points;    ///< Lifetime/Recession points
    const EdgeSections                  &sections;           ///< the gauges' sections of the part
    const EdgeSections                  &design_at_sections; ///< the design's at the same stations
    EdgeGauge                            gauge;              ///< their readings (the worst stations)
    double design_thickness = 0; ///< the design's largest plate thickness at the gauge height [m]
    double gauge_height     = 0; ///< where the plate's thickness is gauged, above the design's edge [m]
    double gauge_z          = 0; ///< the gauge height's z in the part's frame [m]
    double design_volume    = 0; ///< [m^3]
    double density          = 0; ///< [kg/m^3]
  };

  /// One update's wear depth rates per bed, read before the part moved (at the places where the
  /// part was then): what the update's record of every criterion is made of.
  struct BedRates
  {
    long                             cycles = 0;   ///< the cycles the update stands for
    const Rates                     *rates  = nullptr; ///< per vertex, per bed, and the worn volumes
    std::vector<double>              depth_before; ///< the wear depth per vertex before the move
    /// per bed: at the followed points, at the points the design's vertices moved to (more than
    /// one bed), at each gauge station's lowest point (edge) and the mean of the two faces' at
    /// the gauge height (faces; 0 where the station had no section)
    std::vector<std::vector<double>> followed, design_points, edge, faces;
  };

  /// A criterion's quantity at every place it is read (after the update; not finite: no reading
  /// there) and each bed's rate of it there (per bed, per place).
  struct Places
  {
    std::vector<double>              values;
    std::vector<std::vector<double>> bed_rates;
  };

  /// A limit that cannot be: the key (in subsection Lifetime) and why.
  struct CriterionRefused : std::runtime_error
  {
    CriterionRefused(std::string key, const std::string &why) : std::runtime_error(why), key(std::move(key)) {}
    std::string key;
  };

  class EndOfLifeCriterion
  {
  public:
    virtual ~EndOfLifeCriterion() = default;

    /// Its name in the log and summary.json's end_of_life_criterion ("maximum depth").
    virtual std::string name() const = 0;
    /// The parameter that sets its limit (in subsection Lifetime: "Maximum depth").
    virtual std::string parameter() const = 0;
    /// Declares its parameters (in subsection Lifetime, which the caller has entered).
    virtual void declare_parameters(dealii::ParameterHandler &prm) const = 0;
    /// Reads them (in subsection Lifetime).
    virtual void parse_parameters(dealii::ParameterHandler &prm) = 0;
    /// Whether a limit is set (a criterion of this run).
    virtual bool active() const = 0;
    /// The limit on value(), the design given: a limit the design makes impossible throws
    /// CriterionRefused, one it makes implausible adds a warning (said on the terminal and in
    /// the summary). 0 when not active().
    virtual double limit(const PartNow &design, std::vector<std::string> &warnings) const = 0;

    /// The quantity after the update (0 on the design).
    virtual double value(const PartNow &now) const = 0;
    /// Each bed's rate of it at the place that ends the life after this update.
    virtual std::vector<double> bed_rates(const PartNow &now, const BedRates &beds) const = 0;
    /// The quantity at all its places and the beds' rates there; empty: one quantity, one place.
    virtual Places places(const PartNow &, const BedRates &) const { return {}; }

    /// The plate wore through within an update: the quantity as the whole update would have
    /// left it, from the part before the move and @p before, its value then (a rival crossing
    /// within the same update). Default: unchanged (not followed through such an update).
    virtual double projected(const PartNow &, const BedRates &, double before) const { return before; }

    /// Where on the part it ended the life (the part's frame); empty: the whole part. After a
    /// projected() crossing @p projected is true and @p deepest is where the plate wore through.
    virtual std::vector<double> where(const PartNow &now, const std::vector<double> &deepest,
                                      bool projected) const = 0;
    /// Its limit in trajectory.png (TrajectoryMarks' field of its quantity; none: not drawn).
    virtual void mark_limit(TrajectoryMarks &) const {}
    /// Whether trajectory.png draws its quantity [m] (and so an extrapolation to its limit).
    virtual bool drawn_in_trajectory() const { return false; }
    /// The section through where it ended the life: what it says of its quantity, read at a
    /// place ("depth below the design ", followed by its value and limit there); of a quantity
    /// of the whole part (section_label() empty) a note before the deepest point's depth ("the
    /// whole part's worn mass ends the life; "); and how it is drawn (an arrow to the design,
    /// the gauge's two levels).
    virtual std::string section_label() const { return {}; }
    virtual std::string whole_part_note() const { return {}; }
    virtual void        section_drawing(SectionMark &mark) const { mark.to_design = true; }
  };

  using EndOfLifeCriterionFactory = std::unique_ptr<EndOfLifeCriterion> (*)();

  /// Every registered criterion, one new instance each, in the order of their names.
  std::vector<std::unique_ptr<EndOfLifeCriterion>> make_end_of_life_criteria();
  /// Declares every registered criterion's parameters (in subsection Lifetime, entered).
  void declare_end_of_life_criteria(dealii::ParameterHandler &prm);

  /// Adds a criterion (ABRADE_REGISTER_END_OF_LIFE_CRITERION); a name registered twice is a bug.
  struct EndOfLifeCriterionRegistration
  {
    explicit EndOfLifeCriterionRegistration(EndOfLifeCriterionFactory make);
  };
} // namespace abrade::coupling::lifetime

/// One line in a criterion's file registers it (at namespace scope).
#define ABRADE_REGISTER_END_OF_LIFE_CRITERION(Class)                                                   \
  ABRADE_REGISTER_PLUGIN(::abrade::coupling::lifetime::EndOfLifeCriterionRegistration,                 \
                         ::abrade::coupling::lifetime::EndOfLifeCriterion, Class)
