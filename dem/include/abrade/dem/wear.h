#pragma once
// Wear of wall meshes, accumulated per triangle and per phase of the operating cycle from the
// particle-wall contacts of every step (shared/reference/physics.md, section 3):
//
//  - archard:  Q = W max(F_n, 0) |v_t| dt (EDEM); fields archard_volume [m^3] and
//              archard_depth = volume / area [m];
//  - relative: cumulative normal energy |F_n v_n| dt and tangential energy |F_t . v_t| dt [J];
//  - finnie:   LIGGGHTS' `wear finnie`: 2 k |v| |F| f(gamma) dt / A, with v the particle
//              centre's velocity relative to the wall, gamma its angle to the triangle's plane,
//              f = cos^2(gamma)/3 for tan(gamma) > 1/3 and sin(2 gamma) - 3 sin^2(gamma)
//              otherwise; no wear while the particle moves away from the wall.
//
// A contact point on an edge or a vertex shared by several triangles is one contact (see
// Simulation); its increment is split equally between the triangles that share that edge or
// vertex (found from the point's barycentric coordinates, within 1e-9), so the total is
// deposited once. Each triangle's share of a depth-like quantity is
// divided by that triangle's own area.
//
// Under MPI each rank records the contacts of its own particles; the accessors return the sums
// over all ranks, so they are collective (every rank calls them, in the same order).
#include <abrade/dem/contact_log.h>
#include <abrade/dem/parallel.h>

#include <map>
#include <string>
#include <vector>

namespace abrade::dem
{
  class Simulation;

  struct WearLaws
  {
    bool   archard             = true;
    double archard_coefficient = 1.0; ///< W = K / H [1/Pa]
    bool   relative            = false;
    bool   finnie              = false;
    double finnie_coefficient  = 1.0; ///< k_finnie [-]
  };

  class WearRecorder : public StepHook
  {
  public:
    enum Field
    {
      archard_volume,
      relative_normal_energy,
      relative_tangential_energy,
      finnie,
      n_fields
    };
    static const char *field_name(Field f);

    /// @p laws: per wall (indexed like the simulation's walls); a wall with no law enabled is
    /// not tracked.
    WearRecorder(const Simulation &sim, std::vector<WearLaws> laws);

    void after_step(const Simulation &sim, const ContactLog &log) override;
    void phase_changed(const Simulation &sim, const std::string &phase) override;

    bool tracks(std::size_t wall, Field f) const;
    /// Per-triangle values of a field, summed over all phases ("") or for one phase.
    std::vector<double> values(std::size_t wall, Field f, const std::string &phase = "") const;
    /// Per-vertex values of a field: each contact's increment split over the vertices of the
    /// triangle that carries it with the barycentric weights of the contact point. Sums to the
    /// per-triangle values' sum. Summed over all phases ("") or for one phase.
    std::vector<double> vertex_values(std::size_t wall, Field f, const std::string &phase = "") const;
    /// archard_volume / area per triangle [m].
    std::vector<double> archard_depth(std::size_t wall, const std::string &phase = "") const;
    /// Sum over triangles.
    double total(std::size_t wall, Field f, const std::string &phase = "") const;
    /// Phases in the order they began.
    const std::vector<std::string> &phases() const { return phase_order; }

  private:
    struct WallData
    {
      WearLaws            laws;
      std::vector<double> area;
      // triangles around each vertex (CSR), to split edge and vertex contacts
      std::vector<int>    vertex_offsets, vertex_triangles;
      std::size_t         n_vertices = 0;
      // phase -> field -> per-triangle values, and per-vertex values
      std::map<std::string, std::vector<std::vector<double>>> data, vertex_data;
    };
    Parallel                 ranks;
    std::vector<WallData>    walls;
    std::vector<std::string> phase_order;
    std::string              current = "-";
    std::vector<int>         share; // scratch: triangles that share a contact's feature

    void deposit(const Simulation &sim, const WallContactRecord &r, Field f, double amount, bool per_area);
  };
} // namespace abrade::dem
