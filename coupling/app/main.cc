// abrade: predicts where and how fast bulk-handling tools wear.
//
//   abrade run [FILE.prm] [--set "Section/Sub/Key=value"]... [--output DIR] [--quiet] [--resume]
//   abrade params [--format text|prm]
//   abrade preview FILE.prm [--set ...]... --output DIR
//   abrade case PART --output FILE.prm [--material NAME] [--clamped SELECTORS] [...]
//   abrade report RUN_DIR
//   abrade export-walls [FILE.prm] --output DIR
//   abrade convert SCRIPT.geo|CAD --output FILE.step
//   abrade compare --predicted WORN --scan SCAN [--reference DESIGN] --output DIR [...]
//   abrade calibrate --run DIR... --measurements FILE.csv --output DIR
//   abrade --version
//
// Exit codes: 0 success, 2 bad input (command line, parameter file, mesh), 3 run-time failure
// (NaN, lost particle, inverted element), 1 anything else.
#include <abrade/common/atomic_file.h>
#include <abrade/common/error.h>
#include <abrade/common/external.h>
#include <abrade/common/termination.h>
#include <abrade/common/hash.h>
#include <abrade/common/json.h>
#include <abrade/common/progress.h>
#include <abrade/common/version.h>
#include <abrade/coupling/case_command.h>
#include <abrade/coupling/concepts.h>
#include <abrade/coupling/jobs.h>
#include <abrade/coupling/knife_parameters.h>
#include <abrade/coupling/parameter_file.h>
#include <abrade/coupling/parameters.h>
#include <abrade/coupling/sweep.h>
#include <abrade/dem/mesh_io.h>
#include <abrade/dem/parallel.h>
#include <abrade/fem/solid_file.h>
#include <abrade/field/commands.h>
#include <abrade/report/report.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <utility>

#include <unistd.h>
#include <ctime>
#include <fstream>
#include <iostream>

using namespace abrade;

namespace
{
  const char *usage = R"(usage:
  abrade run [FILE.prm] [--set "Section/Sub/Key=value"]... [--output DIR] [--quiet] [--resume]
      run the job the parameter file describes (no file: the embedded small default case)
  abrade params [--format text|prm]
      print every parameter with its documentation, unit, allowed range and default
  abrade sweep FILE.prm --vary "Section/Key=v1,v2,..." [--vary "Key2=..."]... [--seeds 1,2,3]
               [--wall knife] [--edge-height 0.04] [--lifetime-updates N] [--jobs N] [--set ...]...
               --output DIR
      run the case for every value (several --vary: every combination) and seed (one settled
      bed per seed and particle parameters, reused), in parallel, and write study.csv/.md (mean
      and std over seeds), plots/*.png and surfaces/*.vtp; with --lifetime-updates, each
      combination's life too, paired against the first's (lifetime/NAME/)
  abrade concepts BASELINE.prm CONCEPT.prm... [--seeds 1,2] [--knives right_knife,left_knife]
                  [--lifetime-updates N] [--jobs N] [--set ...]... --output DIR
      run every knife concept's cycle per bed seed (the same beds for all), and write the
      knives' wear per phase, payload, wear per tonne and the change against the baseline with
      its uncertainty (concepts.md/.csv, wear.png); with --lifetime-updates, each concept's
      knife life too (lifetime/NAME/, lifetime.png)
  abrade preview FILE.prm [--set ...]... --output DIR
      the case's part on its own (the knife job): meshed, checked, and drawn as the case places
      it with its faces coloured by role (wears, clamped, held) and numbered, the face table and
      what each selector took (DIR/report.html, summary.json)
  abrade case PART --output FILE.prm [--material iron-ore-pellets|gravel|coal|soil]
              [--clamped "SELECTORS"] [--depth D] [--travel L] [--particles N] [...]
      write a commented lifetime case around your part: the part dragged through a bed of the
      material, the bed, container, particle size, phases and tonnes per cycle chosen from the
      part (abrade case alone lists every option)
  abrade report RUN_DIR
      write RUN_DIR/report.html, one self-contained page (pictures inlined) for a lifetime,
      knife (a preview), sweep, concepts, compare or calibrate run; those runs write it
      themselves when they end
  abrade export-walls [FILE.prm] [--set ...]... --output DIR
      write every wall of the case, as the simulation sees it at t = 0, as DIR/NAME.stl
  abrade convert SCRIPT.geo|FILE.step|FILE.brep --output FILE.step
      write the CAD model of a Gmsh script (OpenCASCADE kernel) as STEP, its numbers as they
      are (a script in millimetres gives a STEP in millimetres): a part drawn as a script
  abrade --version
)";

  struct CommandLine
  {
    std::string              command;
    std::string              file;
    std::vector<std::string> sets;
    std::string              output;
    std::string              format = "text";
    std::vector<std::string> varies;
    std::string              seeds, wall = "knife"; ///< seeds: each command has its default
    double                   edge_height = 0.04;
    int                      jobs = 0;
    bool                     quiet  = false;
    bool                     resume = false;
    std::vector<std::string> more_files;             ///< concepts: the files after the first
    std::string              knives = "right_knife,left_knife";
    int                      lifetime_updates = 0;
    std::string              command_line; ///< as typed (summary.json's provenance)
  };

  /// What mpirun (Open MPI, or a PMI launcher) told this process, known before MPI_Init.
  struct Launch
  {
    bool by_mpirun = false;
    int  rank = 0, size = 1;
  };
  Launch launch()
  {
    Launch l;
    for (const auto &[rank, size] : {std::pair{"OMPI_COMM_WORLD_RANK", "OMPI_COMM_WORLD_SIZE"}, {"PMI_RANK", "PMI_SIZE"}})
      if (const char *n = std::getenv(size))
        {
          const char *r = std::getenv(rank);
          return {true, r ? std::atoi(r) : 0, std::atoi(n)};
        }
    return l;
  }

  int integer(const std::string &flag, const std::string &v)
  {
    try
      {
        std::size_t used = 0;
        const int   n    = std::stoi(v, &used);
        if (used == v.size())
          return n;
      }
    catch (const std::exception &)
      {
      }
    throw InputError("command line", flag + " needs a whole number, got '" + v + "'");
  }

  double number(const std::string &flag, const std::string &v)
  {
    try
      {
        std::size_t  used = 0;
        const double x    = std::stod(v, &used);
        if (used == v.size() && std::isfinite(x))
          return x;
      }
    catch (const std::exception &)
      {
      }
    throw InputError("command line", flag + " needs a number, got '" + v + "'");
  }

  std::vector<int> seed_list(const std::string &text)
  {
    std::vector<int>  seeds;
    std::stringstream ss(text);
    for (std::string s; std::getline(ss, s, ',');)
      {
        const int seed = integer("--seeds", s);
        if (seed < 0)
          throw InputError("command line", "--seeds: a seed is 0 or more, got " + s);
        if (std::find(seeds.begin(), seeds.end(), seed) != seeds.end())
          throw InputError("command line", "--seeds: seed " + s + " is given twice (the same bed twice is no replicate)");
        seeds.push_back(seed);
      }
    return seeds;
  }

  /// The output directory given on the command line: after --output or -o, or --output=DIR
  /// ("" if none).
  std::string output_option(int argc, char **argv)
  {
    for (int k = 1; k < argc; ++k)
      {
        const std::string a = argv[k];
        if ((a == "--output" || a == "-o") && k + 1 < argc)
          return argv[k + 1];
        if (a.rfind("--output=", 0) == 0)
          return a.substr(9);
      }
    return "";
  }

  /// After a run that ended with @p rc: its report in @p directory (a failed report is a warning,
  /// not a failed run). Returns @p rc.
  int with_report(int rc, const std::string &directory)
  {
    if (rc != 0 || directory.empty())
      return rc;
    try
      {
        std::cout << "Report: " << report::write_report(directory) << std::endl;
      }
    catch (const std::exception &e)
      {
        std::cerr << "warning: no report written: " << e.what() << std::endl;
      }
    return rc;
  }

  CommandLine parse(int argc, char **argv)
  {
    CommandLine cl;
    for (int k = 0; k < argc; ++k)
      cl.command_line += (k ? " " : "") + io::shell_quote(argv[k]);
    std::vector<std::string> a(argv + 1, argv + argc);
    if (a.empty())
      throw InputError("command line", "no command given\n" + std::string(usage));
    cl.command = a[0];
    for (std::size_t k = 1; k < a.size(); ++k)
      {
        auto value = [&](const std::string &flag) {
          if (k + 1 >= a.size())
            throw InputError("command line", flag + " needs a value");
          if (a[k + 1].empty())
            throw InputError("command line", flag + " needs a value (it is empty)");
          return a[++k];
        };
        if (a[k] == "--set")
          cl.sets.push_back(value("--set"));
        else if (a[k].rfind("--set=", 0) == 0)
          cl.sets.push_back(a[k].substr(6));
        else if (a[k] == "--output" || a[k] == "-o")
          cl.output = value("--output");
        else if (a[k] == "--format")
          cl.format = value("--format");
        else if (a[k] == "--vary")
          cl.varies.push_back(value("--vary"));
        else if (a[k] == "--edge-height")
          cl.edge_height = number("--edge-height", value("--edge-height"));
        else if (a[k] == "--seeds")
          cl.seeds = value("--seeds");
        else if (a[k] == "--wall")
          cl.wall = value("--wall");
        else if (a[k] == "--jobs")
          {
            cl.jobs = integer("--jobs", value("--jobs"));
            if (cl.jobs < 0)
              throw InputError("command line", "--jobs must be 0 (one per core) or more, got " + a[k]);
          }
        else if (a[k] == "--knives")
          cl.knives = value("--knives");
        else if (a[k] == "--lifetime-updates")
          cl.lifetime_updates = integer("--lifetime-updates", value("--lifetime-updates"));
        else if (a[k] == "--quiet" || a[k] == "-q")
          cl.quiet = true;
        else if (a[k] == "--resume")
          cl.resume = true;
        else if (!a[k].empty() && a[k][0] == '-')
          throw InputError("command line", "unknown option '" + a[k] + "'");
        else if (cl.file.empty())
          cl.file = a[k];
        else if (cl.command == "concepts")
          cl.more_files.push_back(a[k]);
        else
          throw InputError("command line", "more than one parameter file given ('" + cl.file + "', '" + a[k] + "')");
      }
    return cl;
  }

  /// DIR/parameters.prm: every parameter the run used. When the run reads its parameters from
  /// that very file (`run d/parameters.prm --output d`), it is left as it is if it holds exactly
  /// that, and the run is refused if not (the user's edits would be lost).
  void write_parameters(const coupling::ParameterFile &params, const std::string &canonical,
                        const std::string &path)
  {
    std::error_code ec;
    for (const auto &input : params.files_read())
      if (std::filesystem::equivalent(input, path, ec))
        {
          std::ifstream      in(input);
          std::ostringstream text;
          text << in.rdbuf();
          if (text.str() == canonical)
            return;
          throw InputError(input, "is the output directory's parameters.prm, which the run writes: copy it out of "
                                  "the output directory, or choose another --output");
        }
    io::write_file_atomically(path, canonical);
  }

  int run(const CommandLine &cl)
  {
    const auto start = std::chrono::steady_clock::now();
    io::ProgressLine::set_quiet(cl.quiet);
    coupling::ParameterFile params(cl.file, cl.sets);
    auto &prm = params.handler();
    if (!cl.output.empty())
      {
        prm.enter_subsection("Output");
        prm.set("Directory", cl.output);
        prm.leave_subsection();
      }
    prm.enter_subsection("Output");
    const std::string dir = prm.get("Directory");
    prm.leave_subsection();
    const std::string job_name = prm.get("Job");

    // Under mpirun every rank runs the job (the DEM spread over the ranks, the rest on
    // globally reduced data); rank 0 writes the results, the others into DIR/.rank-N.
    if (launch().by_mpirun)
      coupling::init_mpi_once();
    const dem::Parallel ranks = dem::Parallel::world();
    const bool          root  = ranks.rank() == 0;
    io::OutputDirectory out(root ? dir : dir + "/.rank-" + std::to_string(ranks.rank()), dir);
    const std::string   canonical = params.canonical_text();
    {
      // the ranks agree: a directory refused on one rank (rank 0 holds the lock and looks for
      // links in all of it) ends every rank, not rank 0 alone while the others wait for it
      std::string refused;
      try
        {
          out.claim();
          write_parameters(params, canonical, out.file("parameters.prm"));
        }
      catch (const InputError &e)
        {
          refused = e.what();
        }
      if (ranks.max(refused.empty() ? 0.0 : 1.0) > 0)
        throw InputError(refused.empty() ? dir : "", refused.empty() ? "refused on another MPI rank" : refused);
    }
    io::Log log;
    log.set_echo(root);
    if (!root)
      io::ProgressLine::set_quiet(true);
    log.open(out.file("log.txt"));

    prm.enter_subsection("Simulation");
    const long threads = prm.get_integer("Threads") > 0 ? prm.get_integer("Threads") : dem::default_thread_count(ranks);
    prm.leave_subsection();
    log.line("abrade " + std::string(version_string) + ": job '" + job_name + "' from " + params.file_name() +
             ", output in " + dir + ", " + std::to_string(threads) + " threads" +
             (ranks.distributed() ? " on each of " + std::to_string(ranks.size()) + " MPI ranks" : ""));

    io::Json summary;
    summary["abrade_version"] = version_string;
    summary["job"]            = job_name;
    summary["parameter_file"] = params.file_name();
    summary["parameters_hash"] = io::fnv1a_hex(canonical);
    {
      std::time_t now = std::time(nullptr);
      char        buf[32];
      std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
      summary["started"] = buf;
    }
    summary["command"] = cl.command_line;
    summary["threads"] = threads;
    summary["mpi_ranks"] = static_cast<long>(ranks.size());
    summary["status"]    = "interrupted (SIGTERM, SIGINT or SIGHUP); a lifetime run continues with --resume";
    io::prepare_interrupted_summary(out.file("summary.json"), summary.dump());
    io::Timers           timers;
    io::Json            &results = summary["results"];
    coupling::JobContext ctx{params, out, results, timers, log, cl.resume};
    auto finish = [&](const std::string &status) {
      summary["status"] = status;
      io::Json &t       = summary["timings"];
      for (const auto &[name, seconds] : timers.all())
        t[name] = seconds;
      t["total"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      summary.write(out.file("summary.json"));
    };
    try
      {
        for (const auto &job : coupling::registered_jobs())
          if (job.name == job_name)
            job.run(ctx);
      }
    catch (const std::exception &e)
      {
        // keep what is known about the failed run, then report it as usual
        finish(std::string("failed: ") + e.what());
        log.file_only(std::string("error: ") + e.what());
        if (root && job_name == "lifetime")
          try // the report of what was done before it failed
            {
              log.file_only("Report: " + report::write_report(dir));
            }
          catch (const std::exception &)
            {}
        throw;
      }
    finish("completed"); // (the report shows the summary's status)
    // the report is one of the run's declared outputs: a write that fails (a full disk) fails
    // the run (exit 3); a report that cannot be made of what the run wrote is a warning
    std::string not_done; // (an output the run should have written and has not: no "Done")
    if (root && (job_name == "lifetime" || job_name == "knife"))
      try
        {
          if (job_name == "lifetime")
            report::write_paraview_script(dir);
          std::vector<std::string> missing;
          log.line("Report: " + report::write_report(dir, &missing));
          for (const auto &m : missing)
            not_done += (not_done.empty() ? "" : ", ") + m;
          if (!not_done.empty())
            {
              not_done = "the report lacks its picture(s) " + not_done + " (gnuplot failed: report/*.gp.log)";
              log.line("warning: " + not_done);
            }
        }
      catch (const RunError &e)
        {
          // a report cut short by a full disk is no output: its pieces go, which also makes
          // room for the summary that says the run failed (else it would still say completed)
          std::error_code ec;
          std::filesystem::remove_all(out.file("report"), ec);
          std::filesystem::remove(out.file("report.html.tmp"), ec);
          try
            {
              finish(std::string("failed: ") + e.what());
              log.file_only(std::string("error: ") + e.what());
            }
          catch (const std::exception &)
            {}
          throw;
        }
      catch (const std::exception &e)
        {
          not_done = std::string("no report written: ") + e.what();
          log.line("warning: " + not_done);
        }
    // "Done" only when every output is written; else what is missing, the results kept
    log.line(not_done.empty() ? "Done: " + out.file("summary.json")
                              : "Finished without all its outputs (" + not_done + "): " + out.file("summary.json"));
    return 0;
  }
} // namespace

namespace
{
  /// The final error line. Under mpirun the ranks fail together with the same message (the
  /// DEM's errors are agreed on), so only rank 0 prints it; every rank's log.txt has it.
  void print_error(const char *what, const std::string &message)
  {
    if (dem::Parallel::world().rank() == 0 && launch().rank == 0) // the latter also before MPI_Init
      std::cerr << what << message << std::endl;
  }
} // namespace

int main(int argc, char **argv)
{
  io::install_termination_handlers();
  try
    {
      if (argc >= 2 && (std::string(argv[1]) == "--version" || std::string(argv[1]) == "version"))
        {
          std::cout << "abrade " << version_string << std::endl;
          return 0;
        }
      // --help (or -h) anywhere: the usage of the command given, or of all
      for (int k = 2; k < argc; ++k)
        if (std::string(argv[k]) == "--help" || std::string(argv[k]) == "-h")
          {
            const std::string command = argv[1];
            std::cout << (command == "compare"     ? std::string(field::compare_usage)
                          : command == "calibrate" ? std::string(field::calibrate_usage)
                                                   : std::string(usage));
            return 0;
          }
      if (argc >= 2 && (std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h" ||
                        std::string(argv[1]) == "help"))
        {
          std::cout << usage << field::compare_usage << field::calibrate_usage;
          return 0;
        }
      if (argc >= 2 && std::string(argv[1]) == "report")
        {
          if (argc != 3)
            throw InputError("command line", "usage: abrade report RUN_DIR");
          std::cout << report::write_report(argv[2]) << std::endl;
          return 0;
        }
      if (argc >= 2 && std::string(argv[1]) == "compare")
        return with_report(field::run_compare_command(std::vector<std::string>(argv + 2, argv + argc)),
                           output_option(argc, argv));
      if (argc >= 2 && std::string(argv[1]) == "case")
        return coupling::run_case_command(std::vector<std::string>(argv + 2, argv + argc));
      if (argc >= 2 && std::string(argv[1]) == "calibrate")
        return with_report(field::run_calibrate_command(std::vector<std::string>(argv + 2, argv + argc)),
                           output_option(argc, argv));
      const CommandLine cl = parse(argc, argv);
      if (cl.command == "run")
        return run(cl);
      if (cl.command == "preview") // the case's part on its own: the knife job, its report the preview
        {
          if (cl.output.empty())
            throw InputError("command line", "preview needs --output DIR (the case's own output directory is its "
                                             "run's): abrade preview FILE.prm --output DIR");
          CommandLine knife = cl;
          knife.sets.push_back("Job=knife");
          return run(knife);
        }
      if (cl.command == "params")
        {
          coupling::ParameterFile p;
          if (cl.format == "prm")
            std::cout << p.canonical_text();
          else if (cl.format == "text")
            p.handler().print_parameters(std::cout, dealii::ParameterHandler::Text);
          else
            throw InputError("command line", "--format must be text or prm");
          return 0;
        }
      if (cl.command == "sweep" || cl.command == "concepts")
        if (launch().size > 1)
          throw InputError("command line", "abrade " + cl.command +
                                             " runs its runs side by side itself (--jobs); start it without mpirun");
      if (cl.command == "sweep")
        {
          if (cl.file.empty())
            throw InputError("command line", "sweep needs a parameter file");
          coupling::ParameterFile check(cl.file, cl.sets); // fail early on a bad file
          coupling::SweepOptions  o;
          o.parameter_file = std::filesystem::absolute(cl.file).string();
          for (const auto &v : cl.varies)
            coupling::parse_vary(v, o);
          o.edge_height = cl.edge_height;
          o.seeds = seed_list(cl.seeds.empty() ? "1,2,3" : cl.seeds);
          o.sets = cl.sets, o.output = cl.output, o.wall = cl.wall, o.jobs = cl.jobs, o.quiet = cl.quiet;
          o.lifetime_updates = cl.lifetime_updates;
          io::ProgressLine::set_quiet(cl.quiet);
          return with_report(coupling::run_sweep(o, std::filesystem::canonical("/proc/self/exe").string()), o.output);
        }
      if (cl.command == "concepts")
        {
          coupling::ConceptOptions o;
          o.files.push_back(cl.file);
          o.files.insert(o.files.end(), cl.more_files.begin(), cl.more_files.end());
          for (const auto &f : o.files) // fail early on a bad file
            coupling::ParameterFile check(f, cl.sets);
          o.seeds = seed_list(cl.seeds.empty() ? "1,2" : cl.seeds);
          o.knives.clear();
          std::stringstream ks(cl.knives);
          for (std::string k; std::getline(ks, k, ',');)
            o.knives.push_back(k);
          o.sets = cl.sets, o.output = cl.output, o.jobs = cl.jobs, o.quiet = cl.quiet;
          o.lifetime_updates = cl.lifetime_updates;
          io::ProgressLine::set_quiet(cl.quiet);
          return with_report(coupling::run_concepts(o, std::filesystem::canonical("/proc/self/exe").string()), o.output);
        }
      if (cl.command == "convert")
        {
          if (cl.file.empty() || cl.output.empty())
            throw InputError("command line", "convert needs an input file and --output FILE.step");
          fem::convert_to_step(cl.file, cl.output);
          std::cout << cl.output << "\n";
          return 0;
        }
      if (cl.command == "export-walls")
        {
          if (cl.output.empty())
            throw InputError("command line", "export-walls needs --output DIR");
          coupling::ParameterFile p(cl.file, cl.sets);
          auto                     c = coupling::read_dem_case(p);
          io::OutputDirectory      out(cl.output);
          out.claim();
          io::Log                  log; // to the terminal
          log.set_echo(true);
          coupling::fill_solid_model_walls(c, p, out.root(), log); // the FEM knife's surface, placed
          for (const auto &w : c.walls)
            {
              std::error_code ec;
              for (const auto &input : c.input_files)
                if (std::filesystem::equivalent(input, out.file(w.wall.name + ".stl"), ec))
                  throw InputError(input, "is wall " + w.wall.name + "'s mesh and the file export-walls would write "
                                          "it to: choose another --output");
              dem::write_stl(out.file(w.wall.name + ".stl"), w.wall.mesh);
              std::cout << out.file(w.wall.name + ".stl") << ": " << w.wall.mesh.n_triangles() << " triangles\n";
            }
          return 0;
        }
      throw InputError("command line", "unknown command '" + cl.command + "'\n" + usage);
    }
  catch (const InputError &e)
    {
      print_error("abrade: error: ", e.what());
      return 2;
    }
  catch (const RunError &e)
    {
      print_error("abrade: run failed: ", e.what());
      return 3;
    }
  catch (const std::exception &e)
    {
      // not an input problem (those are InputErrors): a bug, and what to report
      print_error("abrade: internal error: ", std::string(e.what()) + " (a bug in abrade " + version_string +
                                           ", not in the input: please report it with the command line, the "
                                           "parameter file and this line)");
      return 1;
    }
  catch (...)
    {
      print_error("abrade: internal error: ", std::string("an exception of unknown type (a bug in abrade ") +
                                           version_string + ": please report it with the command line and the "
                                                            "parameter file)");
      return 1;
    }
}
