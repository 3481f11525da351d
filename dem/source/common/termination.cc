#include <abrade/common/termination.h>

#include <csignal>
#include <cstdio>
#include <cstring>

#include <fcntl.h>
#include <unistd.h>

namespace abrade::io
{
  namespace
  {
    // set once while the run is set up, read only by the handler (never freed)
    const std::string *summary_path = nullptr, *summary_aside = nullptr, *summary_text = nullptr;

    extern "C" void on_termination(int signal)
    {
      static const char message[] = "\nabrade: interrupted; the last complete checkpoint is kept (a lifetime "
                                    "run continues with --resume)\n";
      [[maybe_unused]] auto written = ::write(2, message, sizeof message - 1);
      if (summary_text)
        {
          const int fd = ::open(summary_aside->c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
          if (fd >= 0)
            {
              written = ::write(fd, summary_text->data(), summary_text->size());
              ::close(fd);
              ::rename(summary_aside->c_str(), summary_path->c_str());
            }
        }
      ::_exit(128 + signal);
    }
  } // namespace

  void install_termination_handlers()
  {
    for (const int s : {SIGTERM, SIGINT, SIGHUP})
      std::signal(s, on_termination);
  }

  void prepare_interrupted_summary(const std::string &path, const std::string &text)
  {
    // the new strings are complete before the handler can see them
    const std::string *aside = new std::string(path + ".tmp"), *p = new std::string(path), *t = new std::string(text);
    summary_path  = p;
    summary_aside = aside;
    summary_text  = t;
  }
} // namespace abrade::io
