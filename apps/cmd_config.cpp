// `facadeslam config --dump slam|semantics|optimise`: the effective settings,
// every key with its value and what it means, as YAML that `replay --config`
// (slam), `replay --semantics-config` (semantics) or `optimise --config`
// (optimise) reads back. Written from the same tables that read the files
// (slam/slam_options.cpp, semantics/optimiser/ga_options.cpp), so it is complete.
#include <filesystem>
#include <iostream>
#include <sstream>
#include <string>

#include "apps/cli_support.hpp"
#include "apps/commands.hpp"
#include "core/util/error.hpp"
#include "core/util/shipped_files.hpp"
#include "semantics/optimiser/ga_options.hpp"
#include "slam/slam_options.hpp"

namespace facadeslam::apps {
namespace config_command {
namespace {

struct Options {
  std::string dump;
  std::filesystem::path from;
};

int run(const Options& o) {
  std::ostringstream text;
  if (o.dump == "slam") {
    text << "# facadeslam SLAM settings (facadeslam replay --config FILE). Every key is optional: a file\n"
            "# sets only what it changes. Unknown keys and out-of-range values are errors.\n"
            "# Written by `facadeslam config --dump slam"
         << (o.from.empty() ? "" : " --from " + o.from.string()) << "`.\n";
    write_slam_settings(text, o.from.empty() ? SlamOptions{} : load_slam_options(o.from));
  } else if (o.dump == "optimise") {
    text << "# facadeslam genetic optimiser settings (facadeslam optimise --config FILE). Thesis III.8 and\n"
            "# IV.4: Goldberg's simple GA over the descriptor's 211-bit genome. Every key is optional: a\n"
            "# file sets only what it changes. Unknown keys and out-of-range values are errors.\n"
            "# Written by `facadeslam config --dump optimise"
         << (o.from.empty() ? "" : " --from " + o.from.string()) << "`.\n";
    semantics::write_ga_settings(text, o.from.empty() ? semantics::GaOptions{} : semantics::load_ga_options(o.from));
  } else {
    // What replay runs with when no --semantics-config is given: the shipped file.
    const std::filesystem::path file = o.from.empty() ? shipped_file("configs/semantics.yaml") : o.from;
    text << "# facadeslam semantic settings (facadeslam replay --semantics-config FILE), as read from\n"
            "# "
         << file.string()
         << ". Every key is optional; model paths are relative to the file's folder.\n"
            "# Written by `facadeslam config --dump semantics`.\n";
    write_semantics_settings(text, load_semantics_options(file));
  }
  std::cout << text.str() << std::flush;
  return 0;
}

}  // namespace
}  // namespace config_command

void add_config_command(CLI::App& app) {
  auto options = std::make_shared<config_command::Options>();
  CLI::App* cmd = app.add_subcommand("config", "Print the effective settings with what each means");
  cmd->add_option("--dump", options->dump,
                  "Which settings: slam (replay --config), semantics (--semantics-config) or optimise (optimise "
                  "--config)")
      ->required()
      ->check(CLI::IsMember({"slam", "semantics", "optimise"}));
  cmd->add_option("--from", options->from, "A settings file read over the defaults first (default: the defaults)")
      ->check(kNonEmptyPath);
  cmd->callback([options] { config_command::run(*options); });
}

}  // namespace facadeslam::apps
