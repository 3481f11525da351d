// abrade run: the job a parameter file describes (Job = dem, bed, part, lifetime), its
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
#include <abrade/coupling/parameters/output_parameters.h>
#include <abrade/coupling/parameters/parameter_file.h>
#include <abrade/coupling/parameters/earlier_printings.h>
#include <abrade/coupling/parameters/simulation_parameters.h>
#include <abrade/dem/parallel.h>
#include <abrade/fem/mpi_once.h>
#include <abrade/report/report.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <sstream>

namespace abrade::app
{
  namespace
  {
    /// DIR/parameters.prm: every parameter the run used. When the run reads its parameters from
    /// that very file (`run d/parameters.prm --output d`), it is left as it is if it holds exactly
    /// that (or that as an earlier abrade printed it: earlier_printings.h), and the run is
    /// refused if not (the user's edits would be lost).
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
            const auto earlier = coupling::earlier_printings(canonical);
            if (text.str() == canonical || std::find(earlier.begin(), earlier.end(), text.str()) != earlier.end())
              return; // (an earlier abrade's run: the same parameters as it printed them)
            throw InputError(input, "is the output directory's parameters.prm, which the run writes: copy it out of "
                                    "the output directory, or choose another --output");
          }
      io::write_file_atomically(path, canonical);
    }
  } // namespace

  namespace
  {
    /// One run of a parameter file's job, in the steps it takes: the parameters read, the
    /// output directory claimed (by every MPI rank, or refused by all), the log opened, the
    /// summary begun (it says "interrupted" until the job ends), the job run (a failure is
    /// written into the summary, with the report of what was done, and thrown on), the report
    /// written, and the last line saying whether every output is there.
    class RunJob
    {
    public:
      explicit RunJob(const CommandLine &cl)
        : cl(cl), start(std::chrono::steady_clock::now()), params(cl.file, cl.sets)
      {}

      int run()
      {
        read_parameters();
        claim_the_output_directory();
        open_the_log();
        begin_the_summary();
        run_the_job();
        finish("completed"); // (the report shows the summary's status)
        const std::string not_done = write_the_report();
        // "Done" only when every output is written; else what is missing, the results kept
        log.line(not_done.empty() ? "Done: " + out->file("summary.json")
                                  : "Finished without all its outputs (" + not_done + "): " + out->file("summary.json"));
        return 0;
      }

    private:
      /// Under mpirun every rank runs the job (the DEM spread over the ranks, the rest on
      /// globally reduced data); rank 0 writes the results, the others into DIR/.rank-N.
      static dem::Parallel ranks_of_the_run()
      {
        if (launch().by_mpirun)
          fem::init_mpi_once();
        return dem::Parallel::world();
      }

      /// The job's name, the output directory (--output over Output/Directory) and threads.
      void read_parameters()
      {
        auto &prm = params.handler();
        if (!cl.output.empty())
          coupling::set_output_directory(params, cl.output);
        dir = coupling::output_directory(params);
        job_name = prm.get("Job");
        job      = coupling::make_job(job_name); // (the pattern of Job checked the name)
        root     = ranks.rank() == 0;
        threads  = coupling::read_thread_count(params, ranks);
        canonical = params.canonical_text();
      }

      /// The directory the run's own (its lock, no links in it) and its parameters.prm, on
      /// every rank: the ranks agree, so that a directory refused on one rank (rank 0 holds
      /// the lock and looks for links in all of it) ends every rank, not rank 0 alone while
      /// the others wait for it.
      void claim_the_output_directory()
      {
        out.emplace(root ? dir : dir + "/.rank-" + std::to_string(ranks.rank()), dir);
        std::string refused;
        try
          {
            out->claim();
            write_parameters(params, canonical, out->file("parameters.prm"));
          }
        catch (const InputError &e)
          {
            refused = e.what();
          }
        if (ranks.max(refused.empty() ? 0.0 : 1.0) > 0)
          throw InputError(refused.empty() ? dir : "", refused.empty() ? "refused on another MPI rank" : refused);
      }

      /// log.txt (rank 0 also on the terminal) and its first line.
      void open_the_log()
      {
        log.set_echo(root);
        if (!root)
          io::ProgressLine::set_quiet(true);
        log.open(out->file("log.txt"));
        log.line("abrade " + std::string(version_string) + ": job '" + job_name + "' from " + params.file_name() +
                 ", output in " + dir + ", " + std::to_string(threads) + " threads" +
                 (ranks.distributed() ? " on each of " + std::to_string(ranks.size()) + " MPI ranks" : ""));
      }

      /// summary.json as it stays if the run is stopped: what ran, how, and "interrupted".
      void begin_the_summary()
      {
        summary["abrade_version"]  = version_string;
        summary["job"]             = job_name;
        summary["parameter_file"]  = params.file_name();
        summary["parameters_hash"] = io::fnv1a_hex(canonical);
        {
          std::time_t now = std::time(nullptr);
          char        buf[32];
          std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
          summary["started"] = buf;
        }
        summary["command"]   = cl.command_line;
        summary["threads"]   = threads;
        summary["mpi_ranks"] = static_cast<long>(ranks.size());
        summary["status"]    = "interrupted (SIGTERM, SIGINT or SIGHUP); a lifetime run continues with --resume";
        io::prepare_interrupted_summary(out->file("summary.json"), summary.dump());
      }

      /// The job itself; a failure is kept in the summary and the log, with the report of what
      /// a lifetime run did before it, and thrown on.
      void run_the_job()
      {
        coupling::JobContext ctx{params, *out, summary["results"], timers, log, cl.resume};
        try
          {
            job->run(ctx);
          }
        catch (const std::exception &e)
          {
            finish(std::string("failed: ") + e.what());
            log.file_only(std::string("error: ") + e.what());
            if (root && job->report().after_a_failure)
              try
                {
                  log.file_only("Report: " + report::write_report(dir));
                }
              catch (const std::exception &)
                {}
            throw;
          }
      }

      /// The summary's status and timings, written.
      void finish(const std::string &status)
      {
        summary["status"] = status;
        io::Json &t       = summary["timings"];
        for (const auto &[name, seconds] : timers.all())
          t[name] = seconds;
        t["total"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        summary.write(out->file("summary.json"));
      }

      /// The report of a job that asks for one (Job::report(), rank 0). It is one of the run's
      /// declared outputs: a write that fails (a full disk) fails the run (exit 3); a report
      /// that cannot be made of what the run wrote is a warning. Returns what is missing ("":
      /// nothing).
      std::string write_the_report()
      {
        std::string not_done;
        if (!root || !job->report().page)
          return not_done;
        try
          {
            if (job->report().paraview_script)
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
            std::filesystem::remove_all(out->file("report"), ec);
            std::filesystem::remove(out->file("report.html.tmp"), ec);
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
        return not_done;
      }

      const CommandLine                                 &cl;
      const std::chrono::steady_clock::time_point        start;
      coupling::ParameterFile                            params;
      const dem::Parallel                                ranks = ranks_of_the_run(); // (after params)
      bool                                               root  = true;
      std::string                                        dir, job_name, canonical;
      std::unique_ptr<coupling::Job>                     job;
      long                                               threads = 1;
      std::optional<io::OutputDirectory>                 out;
      io::Log                                            log;
      io::Json                                           summary;
      io::Timers                                         timers;
    };
  } // namespace

  int run_job(const CommandLine &cl)
  {
    io::ProgressLine::set_quiet(cl.quiet);
    return RunJob(cl).run();
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
