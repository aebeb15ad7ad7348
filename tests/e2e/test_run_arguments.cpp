// The command line of `run` (app/run_arguments.hpp), shared by the one-process and MPI
// programs: options, values, refusals, and the MPI program's PETSc options passed over.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "biphasic/app/run_arguments.hpp"

namespace biphasic {
namespace {

TEST(RunArguments, ReadsEveryOption) {
  const RunArguments r = parse_run_arguments(
      {"case.toml", "-o", "out", "--set", "a=1", "--set=b=2", "--overwrite", "-q"});
  EXPECT_EQ(r.case_path, "case.toml");
  EXPECT_EQ(r.output_dir, "out");
  EXPECT_EQ(r.overrides, (std::vector<std::string>{"a=1", "b=2"}));
  EXPECT_TRUE(r.options.overwrite);
  EXPECT_TRUE(r.options.quiet);
  EXPECT_EQ(parse_run_arguments({"c.toml", "--restart", "d"}).restart_dir, "d");
}

TEST(RunArguments, RefusesWhatItCannotRead) {
  EXPECT_THROW(parse_run_arguments({}), std::invalid_argument);
  EXPECT_THROW(parse_run_arguments({"a.toml", "b.toml"}), std::invalid_argument);
  EXPECT_THROW(parse_run_arguments({"a.toml", "-o"}), std::invalid_argument);
  EXPECT_THROW(parse_run_arguments({"a.toml", "-biphasic_ksp_view"}), std::invalid_argument);
}

TEST(RunArguments, PassesOverForeignOptionsAndTheirValues) {
  const RunArguments r = parse_run_arguments(
      {"-biphasic_mat_mumps_icntl_14", "50", "case.toml", "-biphasic_ksp_view", "-o", "out"},
      /*foreign_options=*/true);
  EXPECT_EQ(r.case_path, "case.toml");
  EXPECT_EQ(r.output_dir, "out");
}

}  // namespace
}  // namespace biphasic
