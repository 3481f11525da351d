#pragma once
// The commands of the `abrade` program (abrade run, abrade sweep, ...): each is a file in
// commands/ that registers itself with one line,
//
//   ABRADE_REGISTER_COMMAND("name", usage, function);
//
// where usage is the command's lines of `abrade --help` and function runs it on the words after
// its name. main.cc finds the command in the registry and turns what it throws into the exit
// code (an InputError 2, a RunError 3). The files are compiled into the program itself (not a
// library), so every registration runs before main().
#include <string>
#include <vector>

namespace abrade::app
{
  /// The words after the command's name, and the whole command line as typed (shell-quoted:
  /// summary.json's provenance).
  using CommandFunction = int (*)(const std::vector<std::string> &args, const std::string &typed);

  struct Command
  {
    std::string     name;
    std::string     usage; ///< "  abrade NAME ...\n      what it does\n"
    CommandFunction run;
  };

  /// Every registered command, by name.
  const std::vector<Command> &registered_commands();

  /// Adds a command (ABRADE_REGISTER_COMMAND); a name registered twice is a bug.
  struct CommandRegistration
  {
    CommandRegistration(const std::string &name, const std::string &usage, CommandFunction run);
  };
} // namespace abrade::app

#define ABRADE_REGISTER_COMMAND_CAT2(a, b) a##b
#define ABRADE_REGISTER_COMMAND_CAT(a, b) ABRADE_REGISTER_COMMAND_CAT2(a, b)
/// One line in a command's file registers it: its name, its usage, its function.
#define ABRADE_REGISTER_COMMAND(name, usage, function)                                                        \
  static const ::abrade::app::CommandRegistration ABRADE_REGISTER_COMMAND_CAT(abrade_command_, __LINE__)( \
    name, usage, function)
