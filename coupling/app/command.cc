// The registry of the program's commands (command.h).
#include "command.h"

namespace abrade::app
{
  using Registry = io::PluginRegistry<Command>;

  CommandRegistration::CommandRegistration(std::unique_ptr<Command> (*make)()) { Registry::add(make, "command"); }

  std::vector<std::unique_ptr<Command>> make_commands() { return Registry::make_all(); }

  std::unique_ptr<Command> make_command(const std::string &name) { return Registry::make(name); }
} // namespace abrade::app
