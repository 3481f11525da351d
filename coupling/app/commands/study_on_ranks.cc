// A study command on MPI ranks (study_on_ranks.h).
#include "study_on_ranks.h"

#include "../command_line.h"

#include <abrade/common/error.h>
#include <abrade/common/progress.h>
#include <abrade/coupling/studies/child_runs.h>
#include <abrade/fem/mpi_once.h>

#include <cstdlib>

namespace abrade::app
{
  int study_on_ranks(const std::function<int()> &study)
  {
    if (launch().by_mpirun)
      {
        // a rank waiting in a collective (for the leader's next batch, or for the others'
        // runs) gives its core to the runs instead of spinning on it (unless the user set it)
        ::setenv("OMPI_MCA_mpi_yield_when_idle", "1", 0);
        fem::init_mpi_once();
      }
    coupling::StudyRanks ranks;
    if (!ranks.leads())
      {
        io::ProgressLine::set_quiet(true);
        return ranks.serve();
      }
    try
      {
        const int code = study();
        ranks.end(code);
        return code;
      }
    catch (const InputError &)
      {
        ranks.end(2);
        throw;
      }
    catch (const RunError &)
      {
        ranks.end(3);
        throw;
      }
  }
} // namespace abrade::app
