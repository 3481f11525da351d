#pragma once
// The `lifetime` job: a part's wear over its working life, by alternating operating cycles
// (DEM, or a known rate) and geometry updates of the part's solid model (FEM). run() reads as
// the algorithm; each step is a member function, and the arithmetic of each step is a function of
// its own with a unit test (tests/unit/test_lifetime_steps.cc):
//
//   set_up()                     part, wear source, outputs; resume from the last checkpoint
//   size_first_update()          a pilot cycle on beds of its own sizes the first update
//   for every update:
//     run_cycles()               one cycle's wear per bed seed, per surface vertex (wear_source.h)
//     filter()                   smoothed over the surface, volume conserving (surface_filter.h),
//                                divided by the vertex areas: wear depth per cycle, per seed and
//                                their mean
//     choose_cycles()            how many cycles this update stands for (update_size.h)
//     move_part()                the mean depth moves the part's surface (offset surface), the
//                                mesh follows, is checked and remeshed (fem/part_model.h); a
//                                step that cannot be remeshed is rejected: back to the checkpoint
//     record()                   wear depth below the design (the definition `abrade compare`
//                                uses), volumes, followed points: trajectory.csv, part series
//     checkpoint()               the part and the loop's state (key = value, state_file.h)
//   finish()                     the life from the whole trajectory, reached or extrapolated
//                                (end_of_life.h), its interval over all updates' beds
//                                (life_interval.h): final_life(), then write_results()
//                                (summary.json), plot() (figures), conclude() (the log)
//
// Every update draws its wear from fresh beds: each seed's bed is settled anew from a seed
// derived from it and the update number (bed_seed()), so the updates are independent samples
// and all of them count in the interval; Lifetime/Target interval adds beds to the updates
// until the life's interval is as narrow as asked.
#include <abrade/coupling/jobs.h>
#include <abrade/coupling/parameters/part_parameters.h>
#include <abrade/coupling/lifetime/edge_gauge.h>
#include <abrade/coupling/lifetime/wear_field_columns.h>
#include <abrade/coupling/lifetime/end_of_life.h>
#include <abrade/coupling/lifetime/end_of_life_criterion.h>
#include <abrade/coupling/lifetime/life_interval.h>
#include <abrade/coupling/lifetime/place_scatter.h>
#include <abrade/coupling/lifetime/state_file.h>
#include <abrade/coupling/lifetime/lifetime_outputs.h>
#include <abrade/coupling/lifetime/wear_rates.h>
#include <abrade/coupling/lifetime/wear_calibration.h>
#include <abrade/coupling/lifetime/wear_source.h>
#include <abrade/coupling/lifetime/checkpoints.h>
#include <abrade/common/csv_writer.h>
#include <abrade/fem/part_model.h>
#include <abrade/fem/solid_output.h>

#include <memory>
#include <set>
#include <string>
#include <vector>

namespace abrade::coupling::lifetime
{
  class LifetimeLoop
  {
  public:
    explicit LifetimeLoop(JobContext &ctx);
    ~LifetimeLoop();
    void run();

  private:
    /// The Lifetime subsection.
    struct Settings
    {
      double                        tonnes_per_cycle = 0;
      std::vector<int>              seeds;
      long                          fixed_cycles = 0;
      double                        fraction     = 0.05;
      double                        smoothing    = 0;
      double                        target_tonnes = 0;
      std::vector<double>           planes;
      std::vector<dealii::Point<3>> recession_points;
      long                          max_updates = 1;
      double                        target_interval = 0; ///< relative half-width; 0: none
      double                        gauge_height = 0;
      long                          gauge_stations = 41;
      long                          max_beds = 0;        ///< per update, with a target interval
      std::string                   calibration_file;    ///< Lifetime/Calibration, resolved; empty: none
    };

    /// The outcome of moving the part by one update.
    struct Step
    {
      bool                         moved = false;
      long                         cycles = 0;
      fem::PartModel::UpdateResult result;
      double                       volume_before = 0;
      std::string                  error;
      fem::SolidSurface            before; ///< the surface the rates were found on
      /// the beds' depth rates where the criteria read the part before the move (the gauges'
      /// points interpolated on the surface: what moves those points)
      BedRates                     beds;
    };

    // the steps of run()
    void      set_up();
    void      take_calibration();
    void      store_wear(const CycleWear &wear, std::vector<int> &beds);
    CycleWear run_cycles();
    void      log_cycle_messages(const CycleWear &wear, const std::string &cycle);
    Rates     filter(const CycleWear &wear);
    long      choose_cycles(const Rates &rates) const;
    Step      move_part(const Rates &rates, long cycles);
    void      record(const CycleWear &wear, const Rates &rates, const Step &step);
    void      log_update(const Rates &rates, const Step &step, double deepest_depth, double swept);
    void      checkpoint();
    bool      stop_here();
    void      finish();

    /// The life the run predicts: the criterion, how it was found, where on the part, and
    /// its interval with the updates it came from (finish()'s parts).
    struct FinalLife
    {
      EndOfLife                        e;
      std::string                      criterion, method;
      std::vector<double>              where;
      LifeInterval                     li;
      const std::vector<UpdateRecord> *interval_records = nullptr;
    };
    FinalLife final_life();
    void      write_results(const FinalLife &f);
    void      write_totals(io::Json &results) const;
    void      write_life(io::Json &results, const FinalLife &f);
    void      write_interval(io::Json &results, const LifeInterval &li);
    void      write_warnings(io::Json &results, const LifeInterval &li);
    void      plot(const FinalLife &f);
    void      conclude(const FinalLife &f);

    void read_settings();
    void build_part();
    bool resume();
    // the parts of resume()
    /// The checkpoint @p file of update @p done, read and checked: this version's format, this
    /// run's parameters, its update.
    StateFile read_checkpoint(const std::string &file, long done) const;
    /// The loop's own state from @p state (counters, tonnes, the trajectory's tonnes, which it
    /// returns), checked.
    std::vector<double> take_loop_state(const StateFile &state, const std::string &file, long done);
    /// Criterion @p c's history, update records and places from @p state (@p t: the
    /// trajectory's tonnes), checked.
    void take_criterion_state(const StateFile &state, const std::string &file, std::size_t c,
                              const std::vector<double> &t, long done);
    void start_afresh();
    /// This update's record of every criterion's quantity (its value after the update, the
    /// beds' relative variance of its rate at the place that ends life); returns the relative
    /// bed-to-bed spread of the deepest point's rate.
    double add_update_records(const PartNow &part, const Step &step);
    /// Each criterion's quantity at its places after this update and the beds' rates there
    /// (place_scatter.h); the factors for the worst place.
    void add_place_scatter(const PartNow &part, const Rates &rates, const Step &step);
    /// The life of the criterion that ends it and its interval, from the trajectory so far.
    LifeInterval current_interval(const EndOfLife &e) const;
    /// The beds of the next update under Lifetime/Target interval.
    void choose_beds();
    /// The gauges' sections of the part as it is and of its design at the same stations.
    void gauge_the_part();
    /// The part as the criteria read it: the part as it is now, or its design.
    PartNow part_now() const;
    PartNow design_now() const;
    // the parts of move_part()
    /// One attempt at moving the part by @p n cycles of @p rates (into @p st.result); from the
    /// second attempt on, from the last checkpoint. Returns the error, or "".
    std::string try_to_move(Step &st, const Rates &rates, long n, int attempt);
    /// @p error as every rank sees it: under MPI one rank's failure, or parts that differ
    /// after the move, fail the step on all (collective).
    std::string agreed_by_the_ranks(std::string error) const;
    /// What the move did that a user should know: meshed first, rebuilt, volume notes.
    void log_how_it_moved(const fem::PartModel::UpdateResult &result);
    /// The end of life within this update (@p st worn through): where and after how many tonnes
    /// the depth first reaches the local thickness, and the other criteria at the update's end.
    void note_worn_through(const Step &st, const Rates &rates, long n);
    /// The beds' rates where the criteria read the part, before it moves (move_part()).
    BedRates rates_at_places(const Rates &rates, long cycles) const;
    /// The criterion of that name (one every run has: the depth, the worn mass).
    std::size_t criterion_named(const std::string &name) const;
    /// The quantities every run keeps whatever its limits: the depth (the worn-through life's
    /// interval, the deepest point's bed spread) and the worn mass (the worn volume's spread).
    static inline const std::string depth_name = "maximum depth", mass_name = "maximum worn mass";
    /// The pilot cycle that sizes the first update (previous_largest).
    void size_first_update();
    /// The wear filter's length from the first cycle (the particle's footprint unless given);
    /// warns once where it is below half the mesh size.
    void resolve_smoothing(const CycleWear &wear);

    JobContext                           &ctx;
    Settings                              s;
    DemCase                               dem_case;
    PartParameters                        part_parameters;
    std::unique_ptr<fem::PartModel>       part_model;
    ProfileFrame                          frame; ///< where the profiles are cut
    EdgeSections                          design_sections; ///< the design's, for the gauges (edge_gauge.h)
    EdgeSections                          sections;        ///< the worn part's, after the last update
    EdgeSections                          design_at_sections; ///< the design's at the same stations
    double                                design_thickness = 0; ///< the design's largest at the gauge height
    std::unique_ptr<fem::SolidOutput>     part_output;
    std::unique_ptr<WearSourceChoice>     source_choice; ///< Lifetime/Wear source
    std::unique_ptr<WearSource>           source;
    std::unique_ptr<LifetimeCheckpoints>  checkpoints;
    io::CsvWriter                         trajectory;
    std::string                           hash;
    std::vector<std::string>              earlier_hashes; ///< (of the parameters as earlier abrades printed them)

    WearFieldColumns             field_columns; ///< the Wear field's outputs' names (trajectory.csv, summary.json)

    // the loop's state (all of it is in the checkpoint)
    long                         update = 0; ///< the update being made (the last one done, after it)
    long                         cycles = 0;
    double                       tonnes = 0;
    double                       wear_total = 0; ///< the Wear field's volume so far [m^3]
    double                       volume0 = 0;
    /// every registered end-of-life criterion (end_of_life_criterion.h) and their limits
    std::vector<std::unique_ptr<EndOfLifeCriterion>> criteria;
    std::vector<Criterion>       limits;
    std::vector<TrajectoryPoint> history;      ///< per update (and the fresh part) the criteria's values
    std::vector<std::string>     trajectory_rows; ///< trajectory.csv's rows as written (rebuilt from them on resume)
    std::vector<std::vector<UpdateRecord>> records; ///< per criterion, per update (life_interval.h)
    /// per criterion: the beds' deviations at each of its places (the design's vertices, the
    /// followed points, the gauge's stations; none for the worn mass), the quantity there after
    /// the last update, and the factor for the worst of them on the interval (place_scatter.h)
    std::vector<PlaceScatter>        place_scatter;
    std::vector<std::vector<double>> place_values;
    std::vector<double>              place_factor;
    WearCalibration              calibration; ///< Lifetime/Calibration (coefficient 0: none)
    long                         beds_now = 0; ///< beds of the next update
    std::vector<int>             beds_of_update; ///< the seeds of the update's beds (bed_seed())
    double                       previous_largest = 0; ///< the last update's largest depth rate (its size)
    bool                         smoothing_checked = false; ///< the filter's length warned about (once)
    double                       particle_radius   = 0;     ///< the largest particle's [m] (the DEM's; 0: none seen)
    std::vector<double>          deepest = {0, 0, 0}; ///< where the wear depth is largest (worn part, its own frame)
    double                       tonnes_per_cycle_now = 0; ///< of the update being made
    long                         surfaces_kept = 0; ///< remeshes inside the worn surface (this run)
    /// updates whose swept volume was more than 2 % off the volume worn (a source of volumes; this run)
    long                         updates_off_volume = 0;
    long                         dem_warnings_now = 0, dem_warnings_total = 0; ///< this update's, this run's
    std::set<std::string>        warning_kinds; ///< the DEM warnings logged (each kind once)
    std::set<std::string>        notes_given;   ///< the wear source's notes logged (CycleWear::notes: each text once)

    // the end of the run
    std::string end = "maximum updates reached";
    bool        worn_through = false;
    double      worn_through_tonnes = 0;
    std::vector<TrajectoryPoint> worn_through_rival; ///< the history with the worn-through update's end
    std::vector<std::string> warnings;
  };
} // namespace abrade::coupling::lifetime
