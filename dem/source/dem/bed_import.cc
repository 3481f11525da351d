// A bed of particles imported from a table or a dump (bed_import.h).
#include <abrade/common/csv_reader.h>
#include <abrade/common/error.h>
#include <abrade/common/file_extension.h>
#include <abrade/common/finite_number.h>
#include <abrade/dem/bed_import.h>
#include <abrade/dem/simulation.h>
#include "bed_columns.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

namespace abrade::dem
{
  namespace
  {
    /// Where the bed's values are among a file's columns (@p column(name): the index of a column,
    /// -1 for none): which names are read (x or xu, radius or diameter, vx, wx or omegax, id),
    /// and the scale of a diameter, decided here once for both formats.
    struct ColumnMap
    {
      int position[3] = {-1, -1, -1}, size = -1, id = -1, velocity[3] = {-1, -1, -1}, spin[3] = {-1, -1, -1};
      double size_to_radius = 1;

      ColumnMap(const std::string &path, const std::function<int(const std::string &)> &column,
                const std::string &what)
      {
        const char *axes[3] = {"x", "y", "z"};
        for (int d = 0; d < 3; ++d)
          {
            position[d] = column(axes[d]) >= 0 ? column(axes[d]) : column(std::string(axes[d]) + "u");
            velocity[d] = column(std::string("v") + axes[d]);
            spin[d]     = column(std::string("w") + axes[d]) >= 0 ? column(std::string("w") + axes[d])
                                                                   : column(std::string("omega") + axes[d]);
            if (position[d] < 0)
              throw InputError(path, what + " has no column '" + axes[d] + "'" +
                                       (column(std::string(axes[d]) + "s") >= 0
                                          ? " (scaled coordinates '" + std::string(axes[d]) + "s': dump x y z instead)"
                                          : std::string()));
          }
        size = column("radius");
        if (size < 0 && (size = column("diameter")) >= 0)
          size_to_radius = 0.5;
        if (size < 0)
          throw InputError(path, what + " has neither a 'radius' nor a 'diameter' column");
        if (column("radius") >= 0 && column("diameter") >= 0)
          throw InputError(path, what + " has both a 'radius' and a 'diameter' column: keep one");
        id = column("id");
      }

      /// Row @p k of the bed from the cells @p cell (index -> number); @p where names the row.
      void fill(BedColumns &bed, std::size_t k, const std::function<double(int)> &cell, const std::string &where,
                double density, int material) const
      {
        bed.x[k] = cell(position[0]), bed.y[k] = cell(position[1]), bed.z[k] = cell(position[2]);
        bed.radius[k] = size_to_radius * cell(size);
        double *v[3] = {&bed.vx[k], &bed.vy[k], &bed.vz[k]}, *w[3] = {&bed.wx[k], &bed.wy[k], &bed.wz[k]};
        for (int d = 0; d < 3; ++d)
          {
            *v[d] = velocity[d] >= 0 ? cell(velocity[d]) : 0.0;
            *w[d] = spin[d] >= 0 ? cell(spin[d]) : 0.0;
          }
        const double id_value = id >= 0 ? cell(id) : double(k);
        if (id_value != std::floor(id_value) || std::abs(id_value) > 9e15)
          throw InputError(where, "the id " + std::to_string(id_value) + " is not a whole number");
        bed.id[k]       = std::int64_t(id_value);
        bed.material[k] = material;
        const double r  = bed.radius[k];
        bed.mass[k]     = density * 4.0 / 3.0 * M_PI * r * r * r;
      }
    };

    /// The column names of a table or dump in lower case; InputError when one comes twice
    /// (X and x are one column here).
    std::vector<std::string> column_names(const std::vector<std::string> &given, const std::string &where)
    {
      std::vector<std::string> names;
      for (const auto &g : given)
        {
          names.push_back(io::lower_case(g));
          if (std::count(names.begin(), names.end(), names.back()) > 1)
            throw InputError(where, "the column '" + g + "' comes twice (names are read ignoring case)");
        }
      return names;
    }

    double number(const std::string &path, long line, const std::string &word, const std::string &column)
    {
      const auto x = io::finite_number(word);
      if (!x)
        throw InputError(path + ":" + std::to_string(line),
                         "'" + word + "' in column '" + column + "' is not a finite number");
      return *x;
    }

    ImportedBed import_csv(BedColumns &bed, std::vector<long> &lines, const std::string &path, double density,
                           int material)
    {
      const io::CsvTable             t     = io::read_csv(path);
      const std::vector<std::string> names = column_names(t.header, path);
      const ColumnMap map(path, [&](const std::string &n) {
        const auto it = std::find(names.begin(), names.end(), n);
        return it == names.end() ? -1 : int(it - names.begin());
      }, "the table");
      bed.resize(t.rows.size());
      lines = t.line;
      for (std::size_t k = 0; k < t.rows.size(); ++k)
        map.fill(bed, k, [&](int c) { return number(path, t.line[k], t.rows[k][c], t.header[c]); },
                 path + ":" + std::to_string(t.line[k]), density, material);
      return {bed.size(), "CSV table", -1};
    }

    /// A LIGGGHTS/LAMMPS text dump, read snapshot by snapshot: the last one is the bed. Every
    /// error names the file and line.
    class DumpReader
    {
    public:
      explicit DumpReader(const std::string &path)
        : path(path)
        , in(path, std::ios::binary)
      {
        if (!in)
          throw InputError(path, "cannot open the bed to import");
        std::error_code size_error;
        file_size = std::filesystem::file_size(path, size_error);
        if (size_error)
          throw InputError(path, "cannot read the size of the bed to import");
      }

      ImportedBed read(BedColumns &bed, std::vector<long> &lines, double density, int material)
      {
        ImportedBed result{0, "LIGGGHTS/LAMMPS dump", -1};
        bool        any = false;
        while (std::getline(in, line))
          {
            ++no;
            if (!line.empty() && line.back() == '\r')
              line.pop_back();
            if (no == 1 && line.compare(0, 3, "\xEF\xBB\xBF") == 0) // a UTF-8 byte order mark
              line.erase(0, 3);
            if (line.find_first_not_of(" \t") == std::string::npos)
              continue;
            if (line.rfind("ITEM: UNITS", 0) == 0 || (line.rfind("ITEM: TIME", 0) == 0 && line.rfind("ITEM: TIMESTEP", 0) != 0))
              {
                next("the value of " + line); // (dump_modify units yes, time yes: before the timestep)
                continue;
              }
            if (line.rfind("ITEM: TIMESTEP", 0) != 0)
              throw InputError(where(), "expected 'ITEM: TIMESTEP' (a LIGGGHTS/LAMMPS text dump), found '" +
                                          line.substr(0, 40) + "'");
            const Snapshot snapshot = read_snapshot_head();
            result.timestep         = snapshot.timestep;
            read_atoms(snapshot, bed, lines, density, material);
            any = true;
          }
        if (!any)
          throw InputError(path, "the dump holds no snapshot");
        result.particles = bed.size();
        return result;
      }

    private:
      const std::string path;
      std::ifstream     in;
      std::uintmax_t    file_size = 0;
      std::string       line;
      long              no = 0; ///< the line read last

      /// What a snapshot's head says, from its timestep to its ITEM: ATOMS line.
      struct Snapshot
      {
        long                     timestep = 0, atoms = 0;
        long                     count_line = 0; ///< where the number of atoms is
        std::vector<std::string> names;          ///< the columns' names
        long                     names_line = 0;
      };

      std::string where() const { return path + ":" + std::to_string(no); }

      /// The next line, which must be there: @p wanted says what it should hold.
      std::string next(const std::string &wanted)
      {
        if (!std::getline(in, line))
          throw InputError(path + ":" + std::to_string(no + 1), "the dump ends where " + wanted + " should follow (cut short?)");
        ++no;
        if (!line.empty() && line.back() == '\r')
          line.pop_back();
        return line;
      }

      long whole(const std::string &word, const std::string &what) const
      {
        const auto x = io::finite_number(word);
        if (!x || *x != std::floor(*x) || *x < 0 || *x > 9e15)
          throw InputError(where(), "'" + word + "' is not a " + what);
        return long(*x);
      }

      /// After ITEM: TIMESTEP: the timestep, the number of atoms, the box (skipped) and the
      /// columns' names.
      Snapshot read_snapshot_head()
      {
        Snapshot s;
        s.timestep = whole(next("the timestep"), "timestep");
        if (next("ITEM: NUMBER OF ATOMS").rfind("ITEM: NUMBER OF ATOMS", 0) != 0)
          throw InputError(where(), "expected 'ITEM: NUMBER OF ATOMS'");
        s.atoms      = whole(next("the number of atoms"), "number of atoms");
        s.count_line = no;
        if (next("ITEM: BOX BOUNDS").rfind("ITEM: BOX BOUNDS", 0) != 0)
          throw InputError(where(), "expected 'ITEM: BOX BOUNDS'");
        for (int d = 0; d < 3; ++d)
          next("the box bounds");
        const std::string atoms = next("ITEM: ATOMS");
        if (atoms.rfind("ITEM: ATOMS", 0) != 0)
          throw InputError(where(), "expected 'ITEM: ATOMS' and the column names");
        std::istringstream       header(atoms.substr(11));
        std::vector<std::string> given;
        for (std::string w; header >> w;)
          given.push_back(w);
        s.names      = column_names(given, where());
        s.names_line = no;
        return s;
      }

      /// The snapshot's atoms into @p bed (replacing an earlier snapshot's), each one's line in
      /// @p lines.
      void read_atoms(const Snapshot &s, BedColumns &bed, std::vector<long> &lines, double density, int material)
      {
        const ColumnMap map(path + ":" + std::to_string(s.names_line), [&](const std::string &c) {
          const auto it = std::find(s.names.begin(), s.names.end(), c);
          return it == s.names.end() ? -1 : int(it - s.names.begin());
        }, "the dump's ITEM: ATOMS line");
        // a row holds at least a character and a separator per column: a count the rest of the
        // file cannot hold is refused before anything is allocated for it
        const double at_most = double(file_size - std::min<std::uintmax_t>(file_size, std::uintmax_t(in.tellg()))) /
                               (2.0 * double(std::max<std::size_t>(1, s.names.size())));
        if (double(s.atoms) > at_most)
          throw InputError(path + ":" + std::to_string(s.count_line),
                           "the dump announces " + std::to_string(s.atoms) + " atoms; the rest of the file holds at most " +
                             std::to_string(long(at_most)) + " (cut short, or a wrong count)");
        bed.resize(std::size_t(s.atoms));
        lines.assign(std::size_t(s.atoms), 0);
        for (long k = 0; k < s.atoms; ++k)
          {
            next("atom " + std::to_string(k + 1) + " of " + std::to_string(s.atoms));
            lines[std::size_t(k)] = no;
            std::istringstream       row(line);
            std::vector<std::string> cells;
            for (std::string w; row >> w;)
              cells.push_back(w);
            if (cells.size() != s.names.size())
              throw InputError(where(), std::to_string(cells.size()) + " values where the ITEM: ATOMS line names " +
                                          std::to_string(s.names.size()));
            map.fill(bed, std::size_t(k), [&](int c) { return number(path, no, cells[c], s.names[c]); }, where(),
                     density, material);
          }
      }
    };

    ImportedBed import_dump(BedColumns &bed, std::vector<long> &lines, const std::string &path, double density,
                            int material)
    {
      return DumpReader(path).read(bed, lines, density, material);
    }
  } // namespace

  bool is_imported_bed(const std::string &path)
  {
    const std::string e = io::lower_extension(path);
    return e == ".csv" || e == ".dump" || e == ".lammpstrj" || e == ".liggghts";
  }

  ImportedBed import_bed(Simulation &sim, const std::string &path, int material)
  {
    const double density = sim.materials().at(material).density;
    BedColumns        bed;
    std::vector<long> lines; // of each particle in the file
    const ImportedBed result = io::lower_extension(path) == ".csv" ? import_csv(bed, lines, path, density, material)
                                                                   : import_dump(bed, lines, path, density, material);
    replace_particles(sim, path, bed, [&](std::size_t k) {
      return "the particle on line " + std::to_string(lines[k]) + " (id " + std::to_string(bed.id[k]) + ")";
    });
    return result;
  }
} // namespace abrade::dem
