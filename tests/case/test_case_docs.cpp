// docs/case_file.md must hold the reference generated from the schema, and its example must
// be a valid case. Run with BIPHASIC_UPDATE_DOCS=1 to rewrite the generated part.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "biphasic/io/case_file.hpp"

namespace biphasic {
namespace {

const std::string kDocsPath = std::string(BIPHASIC_SOURCE_DIR) + "/docs/case_file.md";
/// Everything after this line in the docs is generated.
const std::string kMarker =
    "<!-- Generated from the schema by case_schema_markdown(); do not edit below this line. -->\n";

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(CaseDocs, ReferenceIsUpToDate) {
  const std::string generated = case_schema_markdown();
  std::string docs = read_text(kDocsPath);
  const auto marker = docs.find(kMarker);
  ASSERT_NE(marker, std::string::npos) << kDocsPath << " lacks the line:\n" << kMarker;

  if (std::getenv("BIPHASIC_UPDATE_DOCS") != nullptr) {
    docs = docs.substr(0, marker) + kMarker + "\n" + generated;
    std::ofstream(kDocsPath) << docs;
  }
  EXPECT_EQ(docs.substr(marker + kMarker.size()), "\n" + generated)
      << kDocsPath << " is out of date: run this test with BIPHASIC_UPDATE_DOCS=1 to regenerate.";
}

TEST(CaseDocs, ReferenceCoversTheSchema) {
  const std::string generated = case_schema_markdown();
  for (const char* key :
       {"`format_version`", "`title`", "`mesh.file`", "`mesh.grading_faces`", "`material.lambda`",
        "`curves.<name>`", "`boundary[i].name`", "`boundary[i].component`", "`boundary[i].vector`",
        "`boundary[i].curve`", "`stabilisation.length`", "`quadrature.points`", "`time.dt`",
        "`time.newton.max_setup_calls`", "`time.newton.reuse_across_steps`",
        "`linear_solver.ordering`", "`output.line_end`", "`output.line`"}) {
    EXPECT_NE(generated.find(key), std::string::npos) << key;
  }
  for (const char* key : {"`mesh.column.nz`", "`mesh.column.grading_faces`",
                          "`mesh.sphere_octant.lc`", "`output.reactions`"}) {
    EXPECT_NE(generated.find(key), std::string::npos) << key;
  }
  // Defaults come from Config, ranges and units from the schema.
  EXPECT_NE(generated.find("| `time.dt` | number | `6.4` | > 0 | s |"), std::string::npos);
  EXPECT_NE(
      generated.find("| `quadrature.points` | integer | `4` | one of 1, 4, 5, 8, 27, 64, 125 |"),
      std::string::npos);
}

TEST(CaseDocs, ExampleIsAValidCase) {
  const std::string docs = read_text(kDocsPath);
  const std::string open = "```toml\n";
  const auto start = docs.find(open);
  ASSERT_NE(start, std::string::npos) << "no ```toml example in " << kDocsPath;
  const auto end = docs.find("```", start + open.size());
  ASSERT_NE(end, std::string::npos);
  const std::string example = docs.substr(start + open.size(), end - start - open.size());
  try {
    const Config config = parse_case(example, "docs/case_file.md example");
    EXPECT_FALSE(config.bcs.empty());
  } catch (const CaseError& error) {
    FAIL() << error.what();
  }
}

}  // namespace
}  // namespace biphasic
