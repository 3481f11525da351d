#pragma once
// A lifetime run that takes a calibration back (Lifetime/Calibration = calibration.json of
// `abrade calibrate`; docs/field.md, docs/lifetime.md "The life and its interval"). The
// best-ranked run's fitted coefficient of the wear law (Archard's W) replaces the case's: every
// cycle's wear is scaled by W_calibrated / W_case (the wear laws are linear in their coefficient,
// so this is the cycle the DEM would give with it, bit for bit where the ratio is a power of two)
// and the fit's relative standard error becomes the life's `calibration` component: to first
// order the life goes as 1 / W, so Var(ln L) gains (se(W) / W)^2 with the fit's degrees of
// freedom (calibration.h: the spatial blocks and the calibrated run's replicate beds).
//
// The fit holds for the footprint it was made with (Lifetime/Smoothing radius of the
// calibrated run, by default its largest particle's radius: the coarse-graining level): the
// calibration records it, and a run with another footprint is warned about. Where calibrate
// fitted the footprint with W from candidate runs at several footprints (footprint_fit.h:
// `footprint.identifiable`), both are taken: the run's Smoothing radius becomes the fitted one
// (unless set), W the fit's at it, and the footprint's uncertainty joins the component: the life's
// change along the ridge W(r), |d ln L / d ln r| se(ln r), in quadrature with se(W) / W of the
// fit at the footprint (plus the candidates' own error in W there over t; without the
// candidates' lives, |d ln W / d ln r| se(ln r) stands for the footprint's share, warned).
#include <abrade/coupling/lifetime/wear_source.h>

#include <memory>
#include <string>

namespace abrade::coupling::lifetime
{
  struct WearCalibration
  {
    std::string file;                   ///< the calibration.json read
    std::string run;                    ///< the calibrated run's folder (as calibration.json names it)
    std::string wear_field;             ///< the wear field (law) W belongs to; empty: not recorded
    bool        extrapolated = false;   ///< the fit reached past the calibrated run's last update
    double      coefficient     = 0;    ///< the fitted coefficient (W) [1/Pa]
    double      relative_sd     = 0;    ///< its standard error over itself
    double      dof             = 0;    ///< of that standard error
    double      smoothing_radius = 0;   ///< [m] the footprint W holds for; 0: not recorded
    double      particle_radius  = 0;   ///< [m] the largest particle W was fitted with; 0: not recorded
    double      coarse_graining_factor = 0; ///< of the fit's particles at the part (DemCase::factor_at_tools); 0: not recorded
    /// the footprint was fitted with W (calibration.json `footprint`, identifiable): W and
    /// smoothing_radius are the fit's, and relative_sd holds the footprint's share too
    bool        footprint = false;
    double      footprint_relative_sd = 0; ///< the life's, from the footprint along the ridge W(r)
    /// the candidates had no predicted lives (calibration.json `dlnlife_dlnr` 0): the life's
    /// slope along the ridge taken as d ln W / d ln r (the life at a fixed W taken as not
    /// depending on the footprint; on the knife-bed it goes as r^0.71): warned
    bool        footprint_slope_assumed = false;
  };

  /// Reads the best-ranked run of calibration.json @p path; an InputError names the file and
  /// what is missing or wrong (not JSON, no runs, no positive coefficient, a negative standard
  /// error or one larger than W, a negative footprint).
  WearCalibration read_wear_calibration(const std::string &path);

  /// @p source with every cycle's wear scaled to the coefficient @p coefficient (its own
  /// wear_coefficient() must be positive: a DEM wear law's).
  std::unique_ptr<WearSource> make_calibrated_wear_source(std::unique_ptr<WearSource> source, double coefficient);
} // namespace abrade::coupling::lifetime
