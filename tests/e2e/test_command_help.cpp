// Help per command end to end: biphasic COMMAND --help (or -h, or biphasic help COMMAND) prints
// that command's usage with every option it takes to stdout and exits 0 without running
// anything; the whole program's help is unchanged; an unknown command's help is an error.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "../common/run_binary.hpp"

namespace {

using namespace biphasic::e2e;

struct CommandOptions {
  std::string command;
  std::vector<std::string> listed;  ///< what its help must name
};

const std::vector<CommandOptions> kCommands = {
    {"run",
     {"usage:", "biphasic run CASE.toml", "CASE.toml", "-o, --output DIR", "--overwrite",
      "--restart DIR", "--set KEY=VALUE", "-q, --quiet", "-h, --help", "BIPHASIC_PROGRESS_INTERVAL",
      "exit status"}},
    {"check",
     {"usage:", "biphasic check CASE.toml", "--set KEY=VALUE", "-h, --help", "exit status"}},
    {"schema", {"usage:", "biphasic schema", "-h, --help", "exit status"}},
    {"help", {"usage:", "biphasic help [COMMAND]", "COMMAND", "-h, --help", "exit status"}},
};

void expect_lists(const Result& r, const CommandOptions& c, const std::string& how) {
  EXPECT_EQ(r.status, 0) << how << ":\n" << r.output;
  for (const std::string& s : c.listed)
    EXPECT_NE(r.output.find(s), std::string::npos) << how << " lacks '" << s << "':\n" << r.output;
  EXPECT_EQ(r.output.find("error:"), std::string::npos) << how << ":\n" << r.output;
}

TEST(CommandHelp, EveryCommandListsItsOptions) {
  for (const CommandOptions& c : kCommands) {
    expect_lists(run(c.command + " --help"), c, c.command + " --help");
    expect_lists(run(c.command + " -h"), c, c.command + " -h");
    expect_lists(run("help " + c.command), c, "help " + c.command);
  }
}

TEST(CommandHelp, GoesToStdout) {
  // run() joins stderr to stdout: with stderr discarded the help must still be there.
  for (const CommandOptions& c : kCommands) {
    const Result r = run(c.command + " --help 2>/dev/null");
    EXPECT_EQ(r.status, 0) << c.command;
    EXPECT_NE(r.output.find("usage:"), std::string::npos) << c.command << ":\n" << r.output;
  }
}

TEST(CommandHelp, RunsNothingEvenWithACaseFile) {
  const FreshDir w("biphasic_command_help");
  const Result r = run("run " + (w.dir / "missing.toml").string() + " -o " +
                       (w.dir / "out").string() + " --help");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("--restart DIR"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(w.dir / "out"));
}

TEST(CommandHelp, TheProgramHelpIsKeptAndPointsToTheCommands) {
  for (const char* how : {"--help", "-h", "help"}) {
    const Result r = run(how);
    EXPECT_EQ(r.status, 0) << how;
    for (const char* s :
         {"biphasic run CASE.toml [-o DIR]", "biphasic check CASE.toml", "biphasic schema",
          "biphasic --help | --version", "biphasic COMMAND --help", "Exit status"})
      EXPECT_NE(r.output.find(s), std::string::npos) << how << " lacks '" << s << "'";
  }
}

TEST(CommandHelp, AnUnknownCommandIsAnError) {
  const Result r = run("help frobnicate");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.output.find("unknown command 'frobnicate'"), std::string::npos) << r.output;
  const Result s = run("schema --jsn");
  EXPECT_EQ(s.status, 1);
  EXPECT_NE(s.output.find("schema takes no arguments"), std::string::npos) << s.output;
}

}  // namespace
