// A lifetime run that takes a calibration back (wear_calibration.h).
#include <abrade/common/error.h>
#include <abrade/coupling/lifetime/wear_calibration.h>

#include <boost/math/distributions/students_t.hpp>
#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <cmath>

namespace abrade::coupling::lifetime
{
  namespace
  {
    namespace pt = boost::property_tree;

    /// A finite number @p key of @p tree, else an InputError of @p path naming @p whose.
    double required_number(const pt::ptree &tree, const std::string &key, const std::string &path,
                           const std::string &whose)
    {
      const auto v = tree.get_optional<double>(key);
      if (!v || !std::isfinite(*v))
        throw InputError(path, whose + " has no number '" + key + "'");
      return *v;
    }

    /// The best-ranked run of calibrate's 'runs' list: its W, the fit's and the replicates'
    /// errors, the footprint and particles it was made with.
    void read_best_run(const pt::ptree &best, const std::string &path, WearCalibration &c)
    {
      const auto number = [&](const std::string &key) { return required_number(best, key, path, "the best run"); };
      c.run              = best.get<std::string>("run", "");
      c.coefficient      = number("archard_coefficient");
      const double scale = number("scale");
      const double se_fit = number("scale_standard_error_fit"), se_rep = number("scale_standard_error_replicates");
      if (se_fit < 0 || se_rep < 0)
        throw InputError(path, "the best run's standard errors are negative");
      const double se = std::hypot(se_fit, se_rep);
      c.dof           = number("degrees_of_freedom");
      if (!(c.coefficient > 0) || !(scale > 0))
        throw InputError(path, "the best run's fitted coefficient is not positive (its wear does not match the "
                               "measurements: see its calibration.md)");
      if (!(c.dof >= 1))
        throw InputError(path, "the best run's fit has no degrees of freedom (too few measurement blocks for an "
                               "interval): its W cannot carry an uncertainty into the life");
      c.relative_sd = se / scale;
      if (!(c.relative_sd <= 1))
        throw InputError(path, "the best run's W is uncertain by more than itself (standard error " +
                                 std::to_string(100 * c.relative_sd) + " %): not a calibration to run a life on");
      c.smoothing_radius       = best.get<double>("smoothing_radius", 0.0);
      c.particle_radius        = best.get<double>("particle_radius", 0.0);
      c.coarse_graining_factor = best.get<double>("coarse_graining_factor", 0.0);
      if (!(c.particle_radius >= 0) || !(c.coarse_graining_factor >= 0))
        throw InputError(path, "the best run's particle_radius or coarse_graining_factor is negative or not a number");
      if (!(c.smoothing_radius >= 0) || !std::isfinite(c.smoothing_radius))
        throw InputError(path, "the best run's smoothing_radius is negative or not a number");
      c.wear_field   = best.get<std::string>("wear_field", "");
      c.extrapolated = best.get<bool>("extrapolated", false);
    }

    /// The footprint fit (W and the smoothing radius together), where calibrate could identify
    /// one: it replaces the best run's W and radius, and its errors join W's.
    void read_footprint(const pt::ptree &fp, const std::string &path, WearCalibration &c)
    {
      const auto fnumber = [&](const std::string &key) { return required_number(fp, key, path, "the footprint fit"); };
      const double r = fnumber("smoothing_radius"), w = fnumber("wear_coefficient"),
                   sd_log_r = fnumber("log_smoothing_radius_standard_error"), dof = fnumber("degrees_of_freedom");
      if (!(r > 0) || !(w > 0) || !(sd_log_r >= 0) || !(dof >= 1))
        throw InputError(path, "the footprint fit's numbers are out of range (smoothing_radius, wear_coefficient, "
                               "log_smoothing_radius_standard_error, degrees_of_freedom)");
      c.footprint_slope_assumed = fnumber("dlnlife_dlnr") == 0;
      const double slope = c.footprint_slope_assumed ? fnumber("dlnw_dlnr") : fnumber("dlnlife_dlnr");
      c.footprint = true, c.smoothing_radius = r, c.coefficient = w;
      // W's error given the footprint: the fit's at the fitted footprint (a calibration.json
      // without log_wear_coefficient_standard_error has the best-ranked run's only)
      if (const auto sd_log_w = fp.get_optional<double>("log_wear_coefficient_standard_error"))
        {
          const double w_dof = fp.get<double>("wear_coefficient_degrees_of_freedom", c.dof);
          if (!(*sd_log_w >= 0 && *sd_log_w <= 1) || !(w_dof >= 1))
            throw InputError(path, "the footprint fit's log_wear_coefficient_standard_error or "
                                   "wear_coefficient_degrees_of_freedom is out of range");
          // (and the candidates' own error in W at the footprint, footprint_fit.h: a widening of
          // its 95 % half-width, here over t(w_dof) like the rest)
          const double widening = fp.get<double>("log_wear_coefficient_candidate_sensitivity", 0.0);
          if (!(widening >= 0 && widening <= 1))
            throw InputError(path, "the footprint fit's log_wear_coefficient_candidate_sensitivity is out of range");
          const double t = boost::math::quantile(boost::math::students_t_distribution<double>(w_dof), 0.975);
          c.relative_sd = *sd_log_w + widening / t, c.dof = w_dof;
        }
      c.footprint_relative_sd = std::abs(slope) * sd_log_r;
      c.relative_sd           = std::hypot(c.relative_sd, c.footprint_relative_sd);
      c.dof                   = std::min(c.dof, dof);
    }
  } // namespace

  WearCalibration read_wear_calibration(const std::string &path)
  {
    pt::ptree tree;
    try
      {
        pt::read_json(path, tree);
      }
    catch (const pt::json_parser_error &e)
      {
        throw InputError(path, "not a calibration.json of abrade calibrate (" + e.message() + ", line " +
                                 std::to_string(e.line()) + ")");
      }
    const auto runs = tree.get_child_optional("runs");
    if (!runs || runs->empty())
      throw InputError(path, "no calibrated run in it (no 'runs' list)");
    if (!runs->front().first.empty()) // (a JSON object's children have names, a list's do not)
      throw InputError(path, "'runs' is not a list of calibrated runs");
    WearCalibration c;
    c.file = path;
    read_best_run(runs->front().second, path, c); // (ranked: the best first)
    if (const auto fp = tree.get_child_optional("footprint"); fp && fp->get<bool>("identifiable", false))
      read_footprint(*fp, path, c);
    return c;
  }

  namespace
  {
    class CalibratedWearSource : public WearSource
    {
    public:
      CalibratedWearSource(std::unique_ptr<WearSource> source, double coefficient)
        : source(std::move(source)), coefficient(coefficient)
      {}

      CycleWear cycle(const fem::SolidSurface &surface, double tonnes, const std::vector<int> &bed_seeds) override
      {
        CycleWear    w     = source->cycle(surface, tonnes, bed_seeds);
        const double scale = coefficient / source->wear_coefficient();
        for (auto &bed : w.seed_volume)
          for (double &v : bed)
            v *= scale;
        for (double &v : w.phase_volume)
          v *= scale;
        return w;
      }
      std::vector<std::string> phases() const override { return source->phases(); }
      double                   wear_coefficient() const override { return coefficient; }
      bool                     removes_volume() const override { return source->removes_volume(); }
      std::string              name() const override { return source->name(); }

    private:
      std::unique_ptr<WearSource> source;
      double                      coefficient;
    };
  } // namespace

  std::unique_ptr<WearSource> make_calibrated_wear_source(std::unique_ptr<WearSource> source, double coefficient)
  {
    return std::make_unique<CalibratedWearSource>(std::move(source), coefficient);
  }
} // namespace abrade::coupling::lifetime
