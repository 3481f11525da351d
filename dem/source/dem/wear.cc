// The wear recorder: each contact's wear by the walls' wear laws, per triangle and phase (wear.h,
// wear_law.h).
#include <abrade/dem/simulation.h>
#include <abrade/dem/wear.h>

#include <algorithm>
#include <cmath>

namespace abrade::dem
{
  const WearLaw *law_recording(const WallWearLaws &laws, const std::string &field)
  {
    for (const auto &law : laws)
      for (const auto &f : law->fields())
        if (f.name == field)
          return law.get();
    return nullptr;
  }

  /// Where one law's increments go: into its fields of one wall.
  class WearRecorder::Deposit : public WearDeposit
  {
  public:
    Deposit(WearRecorder &recorder, const Simulation &sim, int wall) : recorder(recorder), sim(sim), w(wall) {}
    void add(const WallContactRecord &contact, int field, double amount) override
    {
      recorder.deposit(sim, contact, first + field, amount);
    }
    int wall() const override { return w; }
    int first = 0; ///< the law's first field in the wall's fields

  private:
    WearRecorder     &recorder;
    const Simulation &sim;
    int               w;
  };

  WearRecorder::WearRecorder(const Simulation &sim, std::vector<WallWearLaws> laws) : ranks(sim.parallel())
  {
    walls.resize(sim.n_walls());
    for (std::size_t w = 0; w < sim.n_walls(); ++w)
      {
        WallData           &d    = walls[w];
        const TriangleMesh &mesh = sim.wall(w).mesh;
        if (w < laws.size())
          d.laws = laws[w];
        for (const auto &law : d.laws)
          {
            d.first_field.push_back(int(d.fields.size()));
            for (const auto &f : law->fields())
              d.fields.push_back(f);
          }
        d.area.resize(mesh.n_triangles());
        d.n_vertices = mesh.vertices.size();
        for (std::size_t t = 0; t < mesh.n_triangles(); ++t)
          d.area[t] = mesh.area(t);
        d.vertex_offsets.assign(mesh.vertices.size() + 1, 0);
        for (const auto &t : mesh.triangles)
          for (int v : t)
            ++d.vertex_offsets[v + 1];
        for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
          d.vertex_offsets[v + 1] += d.vertex_offsets[v];
        d.vertex_triangles.resize(d.vertex_offsets.back());
        std::vector<int> fill(d.vertex_offsets.begin(), d.vertex_offsets.end() - 1);
        for (std::size_t t = 0; t < mesh.n_triangles(); ++t)
          for (int v : mesh.triangles[t])
            d.vertex_triangles[fill[v]++] = static_cast<int>(t);
      }
  }

  int WearRecorder::WallData::field_index(const std::string &name) const
  {
    for (std::size_t f = 0; f < fields.size(); ++f)
      if (fields[f].name == name)
        return int(f);
    return -1;
  }

  bool WearRecorder::tracks(std::size_t wall, const std::string &field) const
  {
    return walls[wall].field_index(field) >= 0;
  }

  void WearRecorder::phase_changed(const Simulation &, const std::string &phase)
  {
    current = phase;
    if (std::find(phase_order.begin(), phase_order.end(), phase) == phase_order.end())
      phase_order.push_back(phase);
  }

  void WearRecorder::deposit(const Simulation &sim, const WallContactRecord &r, int f, double amount)
  {
    WallData  &d        = walls[r.wall];
    const bool per_area = d.fields[f].per_area;
    auto      &per      = d.data[current];
    if (per.empty())
      per.assign(d.fields.size(), std::vector<double>(d.area.size(), 0.0));
    // triangles that share the contact point: from its barycentric coordinates in the carrying
    // triangle (robust where round-off calls a point on an edge interior): none ~ 0 -> this
    // triangle; one ~ 0 -> the edge opposite that corner; two ~ 0 -> the remaining corner
    const Wall &wall = sim.wall(r.wall);
    const auto &tris = wall.mesh.triangles;
    const auto &t    = tris[r.triangle];
    const Vec3  a(&wall.current[3 * t[0]]), b(&wall.current[3 * t[1]]), c(&wall.current[3 * t[2]]);
    const Vec3  p(r.point[0], r.point[1], r.point[2]);
    const Vec3  n      = (b - a).cross(c - a);
    const double inv   = 1 / n.squaredNorm();
    const double bary[3] = {n.dot((c - b).cross(p - b)) * inv, n.dot((a - c).cross(p - c)) * inv,
                            n.dot((b - a).cross(p - a)) * inv};
    int on[3], n_on = 0;
    for (int k = 0; k < 3; ++k)
      if (bary[k] < 1e-9)
        on[n_on++] = k;
    share.clear();
    if (n_on == 0 || n_on == 3)
      share.push_back(r.triangle);
    else
      {
        // n_on == 1: the edge of the two other corners; n_on == 2: the third corner alone
        int corners[2], n_c = 0;
        for (int k = 0; k < 3; ++k)
          if (std::find(on, on + n_on, k) == on + n_on)
            corners[n_c++] = t[k];
        const int va = corners[0], vb = n_c > 1 ? corners[1] : -1;
        for (int k = d.vertex_offsets[va]; k < d.vertex_offsets[va + 1]; ++k)
          {
            const int   o  = d.vertex_triangles[k];
            const auto &to = tris[o];
            if (vb < 0 || to[0] == vb || to[1] == vb || to[2] == vb)
              share.push_back(o);
          }
      }
    const double part = amount / share.size();
    for (int o : share)
      per[f][o] += per_area ? part / d.area[o] : part;

    // on the vertices, where it happened: barycentric weights of the point (clamped to the
    // triangle, against round-off), normalised so that the whole increment is deposited
    auto &at_vertices = d.vertex_data[current];
    if (at_vertices.empty())
      at_vertices.assign(d.fields.size(), std::vector<double>(d.n_vertices, 0.0));
    double w[3], sum = 0;
    for (int k = 0; k < 3; ++k)
      sum += (w[k] = std::max(0.0, bary[k]));
    const double scale = per_area ? 1 / d.area[r.triangle] : 1.0;
    for (int k = 0; k < 3; ++k)
      at_vertices[f][t[k]] += (sum > 0 ? w[k] / sum : 1.0 / 3) * amount * scale;
  }

  void WearRecorder::after_step(const Simulation &sim, const ContactLog &log)
  {
    for (std::size_t w = 0; w < walls.size(); ++w)
      {
        Deposit deposit(*this, sim, int(w));
        for (std::size_t k = 0; k < walls[w].laws.size(); ++k)
          {
            deposit.first = walls[w].first_field[k];
            walls[w].laws[k]->record(sim, log, deposit);
          }
      }
  }

  std::vector<double> WearRecorder::values(std::size_t wall, const std::string &field, const std::string &phase) const
  {
    const WallData     &d = walls[wall];
    const int           f = d.field_index(field);
    std::vector<double> out(d.area.size(), 0.0);
    if (f >= 0)
      for (const auto &[name, per] : d.data)
        if (phase.empty() || name == phase)
          for (std::size_t t = 0; t < out.size(); ++t)
            out[t] += per[f][t];
    ranks.sum(out);
    return out;
  }

  std::vector<double> WearRecorder::vertex_values(std::size_t wall, const std::string &field,
                                                  const std::string &phase) const
  {
    const WallData     &d = walls[wall];
    const int           f = d.field_index(field);
    std::vector<double> out(d.n_vertices, 0.0);
    if (f >= 0)
      for (const auto &[name, per] : d.vertex_data)
        if (phase.empty() || name == phase)
          for (std::size_t v = 0; v < out.size(); ++v)
            out[v] += per[f][v];
    ranks.sum(out);
    return out;
  }

  std::vector<double> WearRecorder::depth(std::size_t wall, const std::string &field, const std::string &phase) const
  {
    std::vector<double> v = values(wall, field, phase);
    for (std::size_t t = 0; t < v.size(); ++t)
      v[t] /= walls[wall].area[t];
    return v;
  }

  double WearRecorder::total(std::size_t wall, const std::string &field, const std::string &phase) const
  {
    double s = 0;
    for (double x : values(wall, field, phase))
      s += x;
    return s;
  }
} // namespace abrade::dem
