// tumble_docs, the maintainers' tool that writes the generated tables into
// docs/*.md: it replaces only what lies between a block's markers, refuses a
// file without them before any work, and never blocks on a special file.
#include <sys/stat.h>

#include "../app/cli_fixture.hpp"
#include "app/commands.hpp"

namespace {

class DocsTool : public Cli {
 protected:
  fs::path write(const std::string& name, const std::string& text) const {
    const fs::path p = dir_ / name;
    std::ofstream(p) << text;
    return p;
  }
};

TEST_F(DocsTool, MethodsReplacesOnlyBetweenMarkers) {
  const std::string b = "<!-- BEGIN methods -->\n", e = "<!-- END methods -->";
  const fs::path doc = write("doc.md", "# doc\n" + b + "| old |\n" + e + "\nafter\n");
  const Result r = run("methods '" + doc.string() + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(slurp(doc), "# doc\n" + b + tumble::app::methods_markdown() + e + "\nafter\n");

  const fs::path plain = write("plain.md", "no markers here\n");
  const Result bad = run("methods '" + plain.string() + "'");
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("BEGIN methods"), std::string::npos) << bad.err;
  EXPECT_EQ(slurp(plain), "no markers here\n");
}

TEST_F(DocsTool, AccuracyReplacesOnlyBetweenMarkers) {
  const std::string before = "# doc\nintro\n<!-- BEGIN bench:accuracy-table -->\n| old |\n<!-- END bench:accuracy-table -->\nafter\n";
  const fs::path doc = write("doc.md", before);
  const Result r = run("accuracy '" + doc.string() + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string after = slurp(doc);
  EXPECT_EQ(after.rfind("# doc\nintro\n<!-- BEGIN bench:accuracy-table -->\n| method |", 0), 0u) << after;
  EXPECT_EQ(after.find("| old |"), std::string::npos);
  EXPECT_NE(after.find("\n<!-- END bench:accuracy-table -->\nafter\n"), std::string::npos);
  for (const char* row : {"| rk4 |", "| splitting |", "| peer odeint_rk4_body |", "| peer odeint_rk4_world |"})
    EXPECT_NE(after.find(row), std::string::npos) << row;

  const fs::path plain = write("plain.md", "no markers here\n");
  const Result bad = run("accuracy '" + plain.string() + "'");
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("BEGIN bench:accuracy-table"), std::string::npos) << bad.err;
  EXPECT_EQ(slurp(plain), "no markers here\n");
}

TEST_F(DocsTool, RenderChecksBothBlocksBeforeMeasuring) {
  const fs::path doc = write("doc.md", "<!-- BEGIN bench:render -->\n<!-- END bench:render -->\n");
  const Result r = bounded("render '" + doc.string() + "' -o '" + (dir_ / "out").string() + "'", 20);
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("BEGIN bench:render-dense"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "out")) << "measured before finding the file unfit";
}

TEST_F(DocsTool, SpecialFilesAreRefusedWithoutBlocking) {
  const fs::path doc = dir_ / "README.md";
  ASSERT_EQ(::mkfifo(doc.c_str(), 0644), 0);
  const Result r = bounded("accuracy '" + doc.string() + "'", 20);
  EXPECT_EQ(r.code, 1) << r.err;  // 137: killed by the timeout, it blocked
  EXPECT_NE(r.err.find("README.md: doc file is a FIFO"), std::string::npos) << r.err;
  const Result z = bounded("methods /dev/zero", 20);
  EXPECT_NE(z.code, 0);
  EXPECT_NE(z.code, 137) << "blocked or ran away on /dev/zero";
}

}  // namespace
