#pragma once
// Wear of wall meshes, accumulated per triangle and per phase of the operating cycle from the
// particle-wall contacts of every step, by the wear laws each wall is given (wear_law.h: the
// laws are plugins; docs/physics.md, "Wear laws").
//
// A contact point on an edge or a vertex shared by several triangles is one contact (see
// Simulation); its increment is split equally between the triangles that share that edge or
// vertex (found from the point's barycentric coordinates, within 1e-9), so the total is
// deposited once. Each triangle's share of a per-area field (WearField::per_area) is divided by
// that triangle's own area.
//
// Under MPI each rank records the contacts of its own particles; the accessors return the sums
// over all ranks, so they are collective (every rank calls them, in the same order).
#include <abrade/dem/contact_log.h>
#include <abrade/dem/parallel.h>
#include <abrade/dem/wear_law.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace abrade::dem
{
  class Simulation;

  /// The wear laws of one wall (none: the wall's wear is not tracked).
  using WallWearLaws = std::vector<std::shared_ptr<const WearLaw>>;

  /// The law among @p laws that records field @p field (nullptr: none of them does).
  const WearLaw *law_recording(const WallWearLaws &laws, const std::string &field);

  class WearRecorder : public StepHook
  {
  public:
    /// @p laws: per wall (indexed like the simulation's walls; missing walls have none).
    WearRecorder(const Simulation &sim, std::vector<WallWearLaws> laws);

    void after_step(const Simulation &sim, const ContactLog &log) override;
    void phase_changed(const Simulation &sim, const std::string &phase) override;

    /// The fields of a wall's laws, in the order of its laws.
    const std::vector<WearField> &fields(std::size_t wall) const { return walls[wall].fields; }
    const WallWearLaws           &laws(std::size_t wall) const { return walls[wall].laws; }
    bool                          tracks(std::size_t wall, const std::string &field) const;
    /// Per-triangle values of a field, summed over all phases ("") or for one phase; zeros for
    /// a field the wall does not track.
    std::vector<double> values(std::size_t wall, const std::string &field, const std::string &phase = "") const;
    /// Per-vertex values of a field: each contact's increment split over the vertices of the
    /// triangle that carries it with the barycentric weights of the contact point. Sums to the
    /// per-triangle values' sum. Summed over all phases ("") or for one phase.
    std::vector<double> vertex_values(std::size_t wall, const std::string &field, const std::string &phase = "") const;
    /// A volume field per triangle divided by the triangle's area [m].
    std::vector<double> depth(std::size_t wall, const std::string &field, const std::string &phase = "") const;
    /// Sum over triangles.
    double total(std::size_t wall, const std::string &field, const std::string &phase = "") const;
    /// Phases in the order they began.
    const std::vector<std::string> &phases() const { return phase_order; }

  private:
    struct WallData
    {
      WallWearLaws           laws;
      std::vector<WearField> fields;
      std::vector<int>       first_field; // of each law, into fields
      std::vector<double>    area;
      // triangles around each vertex (CSR), to split edge and vertex contacts
      std::vector<int>    vertex_offsets, vertex_triangles;
      std::size_t         n_vertices = 0;
      // phase -> field -> per-triangle values, and per-vertex values
      std::map<std::string, std::vector<std::vector<double>>> data, vertex_data;
      int field_index(const std::string &name) const;
    };
    class Deposit;

    Parallel                 ranks;
    std::vector<WallData>    walls;
    std::vector<std::string> phase_order;
    std::string              current = "-";
    std::vector<int>         share; // scratch: triangles that share a contact's feature

    void deposit(const Simulation &sim, const WallContactRecord &r, int field, double amount);
  };
} // namespace abrade::dem
