// The registry of the program's commands (command.h).
#include "command.h"

#include <algorithm>
#include <stdexcept>

namespace abrade::app
{
  namespace
  {
    std::vector<Command> &registry()
    {
      static std::vector<Command> commands; // (built before main(), by the registrations)
      return commands;
    }
  } // namespace

  const std::vector<Command> &registered_commands() { return registry(); }

  CommandRegistration::CommandRegistration(const std::string &name, const std::string &usage, CommandFunction run)
  {
    auto &commands = registry();
    if (std::any_of(commands.begin(), commands.end(), [&](const Command &c) { return c.name == name; }))
      throw std::logic_error("command " + name + " registered twice");
    const auto at = std::lower_bound(commands.begin(), commands.end(), name,
                                     [](const Command &c, const std::string &n) { return c.name < n; });
    commands.insert(at, {name, usage, run});
  }
} // namespace abrade::app
