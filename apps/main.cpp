// facadeslam: one command, several subcommands (replay, synth, train,
// evaluate, calibrate, render-map). Errors end the program with one line on
// stderr and a non-zero exit code; never a stack trace, never a hostile
// file's raw bytes (printable() escapes them).
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>

#include "apps/cli_support.hpp"
#include "apps/commands.hpp"
#include "core/util/error.hpp"
#include "core/util/input_confinement.hpp"
#include "core/util/logging.hpp"

namespace {

// "unknown command 'foo' (expected one of: replay, evaluate, ...)" when the
// first word after the global flags names no subcommand (of `evaluate`, for
// the word after it), "missing command (expected one of: ...)" when there is
// none; empty otherwise (and with --help). CLI11 alone says "A subcommand is
// required", which names neither the word that was wrong nor the choices.
std::string subcommand_problem(CLI::App& app, int argc, char** argv) {
  for (int i = 1; i < argc; ++i)
    if (std::string(argv[i]) == "-h" || std::string(argv[i]) == "--help") return {};
  CLI::App* level = &app;
  std::string command = "command";
  const auto choices = [](CLI::App* at, std::string& names) {
    std::vector<CLI::App*> subcommands = at->get_subcommands([](CLI::App* sub) { return !sub->get_name().empty(); });
    for (CLI::App* sub : subcommands) names.append(names.empty() ? "" : ", ").append(sub->get_name());
    return subcommands;
  };
  for (int i = 1; i < argc; ++i) {
    const std::string word = argv[i];
    if (word.empty() || word[0] == '-') {
      if (level != &app) return {};  // a subcommand's own options: CLI11 checks them
      continue;
    }
    std::string names;
    const std::vector<CLI::App*> subcommands = choices(level, names);
    if (subcommands.empty()) return {};
    CLI::App* found = nullptr;
    for (CLI::App* sub : subcommands)
      if (sub->check_name(word)) found = sub;
    if (!found) {
      std::string message = "unknown " + command + " " + facadeslam::quoted_for_message(word);
      return message.append(" (expected one of: ").append(names).append(")");
    }
    level = found;
    command = found->get_name() + " command";
  }
  std::string names;
  if (choices(level, names).empty()) return {};
  return "missing " + command + " (expected one of: " + names + ")";
}

}  // namespace

int main(int argc, char** argv) {
  using namespace facadeslam;
  CLI::App app{"facadeslam: monocular SLAM with semantic facade labelling for outdoor AR"};
  app.require_subcommand(1);
  bool verbose = false, quiet = false;
  app.add_flag("-v,--verbose", verbose, "More log output (debug level)");
  app.add_flag("-q,--quiet", quiet, "Only warnings and errors; no progress bar");
  bool allow_outside_paths = false;
  app.add_flag("--allow-outside-paths", allow_outside_paths,
               "Let paths inside input files (rgb.txt's images, a dataset's train.txt/test.txt names, a scene's "
               "camera and photos) lead outside the file's own folder (refused by default)");
  app.fallthrough();
  app.parse_complete_callback([&] {
    configure_logging(quiet ? Verbosity::quiet : verbose ? Verbosity::verbose : Verbosity::normal);
    allow_paths_outside_inputs(allow_outside_paths);
  });

  apps::add_replay_command(app);
  apps::add_evaluate_command(app);
  apps::add_calibrate_command(app);
  apps::add_synth_command(app);
  apps::add_train_command(app);
  apps::add_optimise_command(app);
  apps::add_render_map_command(app);
  apps::add_config_command(app);

  if (const std::string unknown = subcommand_problem(app, argc, argv); !unknown.empty()) {
    std::fprintf(stderr, "facadeslam: %s (see --help)\n", one_line_message(unknown).c_str());
    return apps::kExitUsage;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::RuntimeError& e) {
    // A subcommand finished with a documented non-zero status (it has
    // already said why).
    return e.get_exit_code();
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);
    std::fprintf(stderr, "facadeslam: %s (see --help)\n", one_line_message(e.what()).c_str());
    return apps::kExitUsage;
  } catch (const Error& e) {
    std::fprintf(stderr, "facadeslam: error: %s\n", one_line_message(e.what()).c_str());
    return apps::kExitError;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "facadeslam: unexpected error: %s\n", one_line_message(e.what()).c_str());
    return apps::kExitError;
  }
  return apps::kExitOk;
}
