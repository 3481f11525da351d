// The command registry of the abrade program (coupling/app/command.h): a command is one file
// with one registration line. Here a toy command registers itself from this file, beside two
// others, and the registry holds all three by name; a name registered twice stops the program.
#include "command.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace
{
  int toy(const std::vector<std::string> &args, const std::string &) { return int(args.size()); }
  int other(const std::vector<std::string> &, const std::string &) { return 7; }

  ABRADE_REGISTER_COMMAND("toy", "  abrade toy [WORDS]...\n      counts its words\n", toy);
  ABRADE_REGISTER_COMMAND("another", "  abrade another\n", other);
  ABRADE_REGISTER_COMMAND("zeta", "  abrade zeta\n", other);
} // namespace

TEST(CommandRegistry, OneLineRegistersACommand)
{
  const auto commands = abrade::app::make_commands();
  ASSERT_EQ(commands.size(), 3u);
  EXPECT_EQ(commands[0]->name(), "another"); // by name: the order of --help
  EXPECT_EQ(commands[1]->name(), "toy");
  EXPECT_EQ(commands[2]->name(), "zeta");
  EXPECT_EQ(commands[1]->run({"a", "b"}, "abrade toy a b"), 2);
  EXPECT_NE(commands[1]->usage().find("counts its words"), std::string::npos);
  EXPECT_EQ(abrade::app::make_command("zeta")->run({}, "abrade zeta"), 7);
  EXPECT_EQ(abrade::app::make_command("frobnicate"), nullptr);
}

// a name registered twice is a bug of the program: said, and it stops
TEST(CommandRegistryDeathTest, ANameRegisteredTwiceStopsTheProgram)
{
  struct Twice : abrade::app::Command
  {
    std::string name() const override { return "toy"; }
    std::string usage() const override { return ""; }
    int         run(const std::vector<std::string> &, const std::string &) const override { return 0; }
  };
  EXPECT_DEATH(abrade::app::CommandRegistration([]() -> std::unique_ptr<abrade::app::Command> {
                 return std::make_unique<Twice>();
               }),
               "the command 'toy' is registered twice");
}
