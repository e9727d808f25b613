// tumble_docs: the maintainers' tool that writes the generated tables into
// the documentation, between a file's <!-- BEGIN/END name --> lines, so that
// no figure there is copied by hand (scripts/doc_figures.sh runs it):
//   tumble_docs methods FILE      core's method table (instant)
//   tumble_docs accuracy FILE     error at 10 s and cost of every method and peer (about a minute)
//   tumble_docs render FILE       frames/s of the demo and of a dense solid (about a minute)
#include <CLI/CLI.hpp>

#include <csignal>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

#include "app/commands.hpp"
#include "base/input_file.hpp"
#include "bench/bench.hpp"
#include "io/atomic_file.hpp"
#ifdef TUMBLE_HAVE_RENDER
#include "bench/render/render_bench.hpp"
#include "render/resource_dir.hpp"
#endif

namespace {

using namespace tumble;

struct DocOptions {
  std::string file;
  long frames = 120;
  std::filesystem::path out_dir = "out/bench";
};

/// The text of `file`, checked to hold each marker's BEGIN/END lines (before
/// minutes of measuring). A regular file only, read without blocking (a FIFO
/// there would hang us); it is rewritten in place, so it is no input that
/// outputs must avoid.
std::string read_doc(const std::string& file, const std::vector<std::string>& markers) {
  constexpr std::size_t kMaxDocBytes = std::size_t{16} << 20;
  const std::string text = read_input_file(file, kMaxDocBytes, "doc file", ReadRole::own_output);
  for (const std::string& m : markers) {
    try {
      bench::replace_between_markers(text, m, "");
    } catch (const InputError& e) {
      throw InputError(file + ": " + e.what());
    }
  }
  return text;
}

int write_methods(const DocOptions& o) {
  const std::string text = read_doc(o.file, {"methods"});
  io::atomic_write_file(o.file, bench::replace_between_markers(text, "methods", app::methods_markdown()));
  std::cout << "wrote the methods table into " << o.file << "\n";
  return app::kOk;
}

int write_accuracy(const DocOptions& o) {
  const std::string text = read_doc(o.file, {"bench:accuracy-table"});
  const std::string table = bench::readme_accuracy_table(std::cout);
  io::atomic_write_file(o.file, bench::replace_between_markers(text, "bench:accuracy-table", table));
  std::cout << table << "wrote the accuracy table into " << o.file << "\n";
  return app::kOk;
}

int write_render(const DocOptions& o) {
#ifdef TUMBLE_HAVE_RENDER
  std::string text = read_doc(o.file, {"bench:render", "bench:render-dense"});
  io::check_output_folder("-o", o.out_dir);
  const std::filesystem::path scenes = render::find_resource_dir() / "scenes";
  const bench::RenderBenchResult r =
      bench::run_render_bench(scenes / "dzhanibekov.toml", o.frames, o.out_dir / "render", std::cout,
                              {scenes / "methods_compare.toml", scenes / "dzhanibekov_explained.toml"});
  const bench::RenderBenchResult d =
      bench::run_render_bench(scenes / "dense_box.toml", o.frames, o.out_dir / "render_dense", std::cout);
  text = bench::replace_between_markers(text, "bench:render", r.markdown);
  io::atomic_write_file(o.file, bench::replace_between_markers(text, "bench:render-dense", d.markdown));
  std::cout << "wrote the render figures into " << o.file << "\n";
  return app::kOk;
#else
  (void)o;
  throw InputError("this build has no renderer (TUMBLE_BUILD_RENDER=OFF)");
#endif
}

}  // namespace

int main(int argc, char** argv) {
  std::signal(SIGXFSZ, SIG_IGN);  // past ulimit -f a write fails with EFBIG, reported, instead of killing us
  CLI::App cli{"Writes tumble's generated tables into a documentation file, between its <!-- BEGIN/END name --> lines",
               "tumble_docs"};
  cli.require_subcommand(1);
  auto o = std::make_shared<DocOptions>();
  app::Action action;
  const auto add = [&](const char* name, const char* help, int (*run)(const DocOptions&)) {
    CLI::App* cmd = cli.add_subcommand(name, help);
    cmd->add_option("file", o->file, "The markdown file to rewrite in place")->required()->check(app::kPath);
    cmd->callback([&action, o, run] { action = [o, run] { return run(*o); }; });
    return cmd;
  };
  add("methods", "The method table (core's MethodInfo rows), between the 'methods' lines", write_methods);
  add("accuracy", "Orientation error at 10 s and ns/step of every method and peer on the T-handle, between the "
                  "'bench:accuracy-table' lines (about a minute)", write_accuracy);
  CLI::App* render = add("render", "Frames/s of the demo and of a 198k-particle solid, between the 'bench:render' and "
                                   "'bench:render-dense' lines (about a minute)", write_render);
  render->add_option("--frames", o->frames, "Frames rendered per measurement")->capture_default_str();
  render->add_option("-o,--out", o->out_dir, "Folder for the frames and videos measured")->capture_default_str()->check(app::kPath);
  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = cli.exit(e);
    return rc == 0 ? 0 : app::kInputError;
  }
  return app::run_action(action);
}
