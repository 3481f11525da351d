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
#include <abrade/common/plugin_registry.h>

#include <memory>
#include <string>
#include <vector>

namespace abrade::app
{
  /// The words after the command's name, and the whole command line as typed (shell-quoted:
  /// summary.json's provenance).
  using CommandFunction = int (*)(const std::vector<std::string> &args, const std::string &typed);

  /// A command: what ABRADE_REGISTER_COMMAND makes of its name, usage and function.
  class Command
  {
  public:
    virtual ~Command() = default;
    virtual std::string name() const = 0;
    /// "  abrade NAME ...\n      what it does\n"
    virtual std::string usage() const = 0;
    virtual int run(const std::vector<std::string> &args, const std::string &typed) const = 0;
  };

  /// One new instance of every registered command, in the order of their names (of --help).
  std::vector<std::unique_ptr<Command>> make_commands();
  /// A new command of that name; nullptr if there is none.
  std::unique_ptr<Command> make_command(const std::string &name);

  /// Adds a command (ABRADE_REGISTER_COMMAND); a name registered twice is a bug.
  struct CommandRegistration
  {
    explicit CommandRegistration(std::unique_ptr<Command> (*make)());
  };
} // namespace abrade::app

/// One line in a command's file registers it, at namespace scope: its name, its usage, its
/// function (a class of those, registered in the one plugin registry).
#define ABRADE_REGISTER_COMMAND(name_, usage_, function_)                                                    \
  namespace                                                                                                \
  {                                                                                                        \
    class ABRADE_PLUGIN_CAT(AbradeCommand, __LINE__) final : public ::abrade::app::Command               \
    {                                                                                                      \
    public:                                                                                                \
      std::string name() const override { return name_; }                                                \
      std::string usage() const override { return usage_; }                                              \
      int run(const std::vector<std::string> &args, const std::string &typed) const override              \
      {                                                                                                    \
        return function_(args, typed);                                                                     \
      }                                                                                                    \
    };                                                                                                     \
  }                                                                                                        \
  ABRADE_REGISTER_PLUGIN(::abrade::app::CommandRegistration, ::abrade::app::Command,                       \
                         ABRADE_PLUGIN_CAT(AbradeCommand, __LINE__))
