// The wear outputs of a DEM run from whatever wear laws its walls have: per-triangle fields of
// the snapshots and the wear tables (wear_tables.h).
#include <abrade/common/csv_writer.h>
#include <abrade/coupling/dem_run/wear_tables.h>

#include <algorithm>

namespace abrade::coupling
{
  std::string max_depth_column(const dem::WearField &field)
  {
    const std::string depth = field.depth_name(); // "archard_depth"
    return depth.substr(0, depth.size() - 5) + "max_depth";
  }

  void add_wear_fields(dem::DemOutput &output, const std::shared_ptr<dem::WearRecorder> &wear, const DemCase &c)
  {
    // every field of any wall, once (walls that do not record it get zeros)
    std::vector<dem::WearField> fields;
    for (std::size_t w = 0; w < c.walls.size(); ++w)
      for (const auto &f : wear->fields(w))
        if (std::none_of(fields.begin(), fields.end(), [&](const dem::WearField &g) { return g.name == f.name; }))
          fields.push_back(f);
    for (const auto &f : fields)
      {
        if (!f.volume)
          {
            output.add_triangle_field(f.name, [wear, name = f.name](const dem::Simulation &, std::size_t w) {
              return wear->values(w, name);
            });
            continue;
          }
        output.add_triangle_field(f.depth_name(), [wear, name = f.name](const dem::Simulation &, std::size_t w) {
          return wear->depth(w, name);
        });
        for (const auto &[phase, duration] : c.phases)
          output.add_triangle_field(f.depth_name() + "_" + phase,
                                    [wear, name = f.name, phase = phase](const dem::Simulation &, std::size_t w) {
                                      return wear->depth(w, name, phase);
                                    });
      }
  }

  void write_wear_table(JobContext &ctx, const dem::Simulation &sim, const dem::WearRecorder &wear, std::size_t w,
                        const std::vector<Phase> &phases, const std::map<std::string, std::vector<double>> &path_length)
  {
    const std::string        &name = sim.wall(w).name;
    std::vector<std::string> columns{"phase"};
    for (const auto &f : wear.fields(w))
      {
        columns.push_back(f.name);
        if (f.volume)
          columns.push_back(max_depth_column(f));
      }
    columns.push_back("path_length");
    io::CsvWriter            csv(ctx.output.file("walls/" + name + "_wear.csv"), columns);
    std::vector<std::string> rows;
    for (const auto &p : phases)
      rows.push_back(p.first);
    rows.push_back(""); // all phases
    for (const auto &phase : rows)
      {
        std::vector<double> row;
        for (const auto &f : wear.fields(w))
          {
            row.push_back(wear.total(w, f.name, phase));
            if (f.volume)
              {
                const auto depth = wear.depth(w, f.name, phase);
                row.push_back(depth.empty() ? 0.0 : *std::max_element(depth.begin(), depth.end()));
              }
          }
        double path = 0; // the wall's centroid's path in the phase (all phases: the sum)
        for (const auto &[p, lengths] : path_length)
          if (phase.empty() || p == phase)
            path += lengths[w];
        row.push_back(path);
        const std::string label = phase.empty() ? "total" : phase;
        csv.row(label, row);
        io::Json &j = ctx.results["wear"][name][label];
        for (std::size_t k = 0; k < row.size(); ++k)
          j[columns[k + 1]] = row[k];
      }
    csv.close();
  }
} // namespace abrade::coupling
