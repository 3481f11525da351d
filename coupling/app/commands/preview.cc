// abrade preview: a case's part on its own before any run -- the part job of the case, whose
// report is the preview (the part placed in the case, its faces by role, the face table).
#include "../command.h"
#include "run_job.h"

#include <abrade/common/error.h>

namespace abrade::app
{
  namespace
  {
    int preview_command(const std::vector<std::string> &args, const std::string &typed)
    {
      CommandLine cl = parse("preview", args, typed, {"FILE", "--set", "--output", "--quiet"});
      if (cl.output.empty())
        throw InputError("command line", "preview needs --output DIR (the case's own output directory is its "
                                         "run's): abrade preview FILE.prm --output DIR");
      cl.sets.push_back("Job=part");
      return run_job(cl);
    }
  } // namespace

  ABRADE_REGISTER_COMMAND("preview",
                          "  abrade preview FILE.prm [--set ...]... --output DIR\n"
                          "      the case's part on its own (the part job): meshed, checked, and drawn as the case places\n"
                          "      it with its faces coloured by role (wears, clamped, held) and numbered, the face table and\n"
                          "      what each selector took (DIR/report.html, summary.json)\n",
                          preview_command);
} // namespace abrade::app
