// In-process fuzzing of abrade's own readers with libFuzzer (clang's -fsanitize=fuzzer), under
// AddressSanitizer and UndefinedBehaviorSanitizer: every input a reader is given either reads
// or ends in an abrade::InputError; anything else (a crash, an out-of-bounds access, undefined
// behaviour, another exception, a hang past -timeout) is a finding, kept by libFuzzer as
// crash-*/timeout-* with the input that made it.
//
// The readers take a path: each input is written to a file of the format's extension in a
// directory of this process's own, and read back through the same call the program makes
// (io::read_polydata dispatches .obj, .ply, .vtk, .stl, .vtp by extension; io::read_csv reads
// measurement tables and imported beds). ABRADE_FUZZ_FORMAT names the format (obj, ply, vtk,
// stl, vtp, csv). Built and run by build_and_run.sh.
#include <abrade/common/csv_reader.h>
#include <abrade/common/error.h>
#include <abrade/common/vtk_input.h>

#include <vtkPolyData.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include <unistd.h>

namespace
{
  const std::string &format()
  {
    static const std::string f = [] {
      const char *e = std::getenv("ABRADE_FUZZ_FORMAT");
      return std::string(e ? e : "obj");
    }();
    return f;
  }

  const std::string &input_path()
  {
    static const std::string path = [] {
      const char *dir = std::getenv("ABRADE_FUZZ_DIR");
      return std::string(dir ? dir : "/tmp") + "/input-" + std::to_string(::getpid()) + "." + format();
    }();
    return path;
  }
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
  {
    std::ofstream out(input_path(), std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char *>(data), std::streamsize(size));
  }
  try
    {
      if (format() == "csv")
        abrade::io::read_csv(input_path());
      else
        {
          const auto p = abrade::io::read_polydata(input_path());
          // what the callers do next: walk every cell's points
          for (vtkIdType c = 0; c < p->GetNumberOfCells(); ++c)
            {
              vtkIdType        n;
              const vtkIdType *ids;
              p->GetCellPoints(c, n, ids);
              for (vtkIdType k = 0; k < n; ++k)
                {
                  double x[3];
                  p->GetPoint(ids[k], x);
                }
            }
        }
    }
  catch (const abrade::InputError &)
    {
    }
  return 0;
}
