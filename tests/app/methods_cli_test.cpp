// `tumble methods`: the README's method table is core's method table, written
// by `tumble methods --readme README.md` and kept equal to it here.
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

TEST(MethodsTable, ReadmeBlockIsTheGeneratedTable) {
  const std::string block = methods_block(read_text(kSource / "README.md"));
  ASSERT_FALSE(block.empty()) << "README.md has no <!-- BEGIN/END methods --> block";
  EXPECT_EQ(block, tumble::app::methods_markdown()) << "run: tumble methods --readme README.md";
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

TEST_F(MethodsCli, ReadmeOptionReplacesOnlyBetweenMarkers) {
  const fs::path doc = dir_ / "doc.md";
  std::ofstream(doc) << "# doc\n" << kBegin << "| old |\n" << kEnd << "\nafter\n";
  const Result r = run("methods --readme '" + doc.string() + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(read_text(doc), "# doc\n" + kBegin + tumble::app::methods_markdown() + kEnd + "\nafter\n");

  const fs::path plain = dir_ / "plain.md";
  std::ofstream(plain) << "no markers here\n";
  const Result bad = run("methods --readme '" + plain.string() + "'");
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("BEGIN methods"), std::string::npos) << bad.err;
  EXPECT_EQ(read_text(plain), "no markers here\n");
}

TEST_F(MethodsCli, MarkdownFlagPrintsTheTable) {
  const Result r = run("methods --markdown");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out, tumble::app::methods_markdown());
  const Result text = run("methods");
  ASSERT_EQ(text.code, 0) << text.err;
  EXPECT_NE(text.out.find("splitting4"), std::string::npos) << text.out;
}

}  // namespace
