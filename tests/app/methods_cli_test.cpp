// `tumble methods`: docs/methods.md's method table is core's method table,
// written by `tumble_docs methods docs/methods.md` and kept equal to it here.
#include "cli_fixture.hpp"

#include "app/commands.hpp"
#include "core/integrator.hpp"

namespace {

const std::string kBegin = "<!-- BEGIN methods -->\n", kEnd = "<!-- END methods -->";

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The lines strictly between the markers, or "" when either is missing.
std::string methods_block(const std::string& doc) {
  const size_t b = doc.find(kBegin);
  if (b == std::string::npos) return "";
  const size_t e = doc.find(kEnd, b + kBegin.size());
  return e == std::string::npos ? "" : doc.substr(b + kBegin.size(), e - b - kBegin.size());
}

TEST(MethodsTable, DocBlockIsTheGeneratedTable) {
  const std::string block = methods_block(read_text(kSource / "docs" / "methods.md"));
  ASSERT_FALSE(block.empty()) << "docs/methods.md has no <!-- BEGIN/END methods --> block";
  EXPECT_EQ(block, tumble::app::methods_markdown()) << "run: scripts/doc_figures.sh --table-only";
}

TEST(MethodsTable, OneLineRowPerMethodFromTheTable) {
  const std::string md = tumble::app::methods_markdown();
  size_t rows = 0;
  for (char c : md) rows += c == '\n';
  EXPECT_EQ(rows, 2 + tumble::kAllMethods.size());  // header, rule, one row each
  for (const tumble::MethodInfo& i : tumble::method_table()) {
    EXPECT_FALSE(i.description.empty()) << i.name;
    EXPECT_EQ(i.description.find('\n'), std::string_view::npos) << i.name;
    EXPECT_NE(md.find("| `" + std::string(i.name) + "` |"), std::string::npos) << i.name;
  }
  EXPECT_NE(md.find("| `rk45` | 5(4) |"), std::string::npos) << md;  // adaptive: order(embedded order)
  EXPECT_NE(md.find("| `exact` | — |"), std::string::npos) << md;    // closed form
  EXPECT_NE(md.find("energy and \\|L\\| to round-off"), std::string::npos) << md;  // '|' escaped
}

class MethodsCli : public Cli {};

// Writing a file is the maintainers' tool's job (tumble_docs), not the user's binary's.
TEST_F(MethodsCli, MarkdownFlagPrintsTheTableAndWritesNoFile) {
  EXPECT_EQ(run("methods --readme x.md").code, 2);
  const Result r = run("methods --markdown");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out, tumble::app::methods_markdown());
  const Result text = run("methods");
  ASSERT_EQ(text.code, 0) << text.err;
  EXPECT_NE(text.out.find("splitting4"), std::string::npos) << text.out;
}

}  // namespace
