// abrade run: the job a parameter file describes (Job = dem, bed, knife, lifetime), its
// summary.json, log.txt and parameters.prm in the output directory, and its report.
#include "run_job.h"

#include "../command.h"

#include <abrade/common/atomic_file.h>
#include <abrade/common/error.h>
#include <abrade/common/hash.h>
#include <abrade/common/json.h>
#include <abrade/common/progress.h>
#include <abrade/common/termination.h>
#include <abrade/common/version.h>
#include <abrade/coupling/jobs.h>
#include <abrade/coupling/part_parameters.h>
#include <abrade/coupling/parameter_file.h>
#include <abrade/dem/parallel.h>
#include <abrade/report/report.h>

#include <chrono>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace abrade::app
{
  namespace
  {
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
  } // namespace

  int run_job(const CommandLine &cl)
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
        coupling::make_job(job_name)->run(ctx); // (the pattern of Job checked the name)
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

  namespace
  {
    int run_command(const std::vector<std::string> &args, const std::string &typed)
    {
      return run_job(parse("run", args, typed, {"FILE", "--set", "--output", "--quiet", "--resume"}));
    }
  } // namespace

  ABRADE_REGISTER_COMMAND("run",
                          "  abrade run [FILE.prm] [--set \"Section/Sub/Key=value\"]... [--output DIR] [--quiet] [--resume]\n"
                          "      run the job the parameter file describes (no file: the embedded small default case)\n",
                          run_command);
} // namespace abrade::app
