// facadeslam: one command, several subcommands (replay, synth, train,
// evaluate, calibrate, render-map). Errors end the program with one line on
// stderr and a non-zero exit code; never a stack trace, never a hostile
// file's raw bytes (printable() escapes them).
#include <cstdio>
#include <exception>

#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>

#include "apps/cli_support.hpp"
#include "apps/commands.hpp"
#include "core/util/error.hpp"
#include "core/util/logging.hpp"

int main(int argc, char** argv) {
  using namespace facadeslam;
  CLI::App app{"facadeslam: monocular SLAM with semantic facade labelling for outdoor AR"};
  app.require_subcommand(1);
  bool verbose = false, quiet = false;
  app.add_flag("-v,--verbose", verbose, "More log output (debug level)");
  app.add_flag("-q,--quiet", quiet, "Only warnings and errors; no progress bar");
  app.fallthrough();
  app.parse_complete_callback([&] {
    configure_logging(quiet ? Verbosity::quiet : verbose ? Verbosity::verbose : Verbosity::normal);
  });

  apps::add_replay_command(app);
  apps::add_evaluate_command(app);
  apps::add_calibrate_command(app);
  apps::add_synth_command(app);
  apps::add_train_command(app);
  apps::add_optimise_command(app);
  apps::add_render_map_command(app);

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
    std::fprintf(stderr, "facadeslam: %s (see --help)\n", printable(e.what()).c_str());
    return apps::kExitUsage;
  } catch (const Error& e) {
    std::fprintf(stderr, "facadeslam: error: %s\n", printable(e.what()).c_str());
    return apps::kExitError;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "facadeslam: unexpected error: %s\n", printable(e.what()).c_str());
    return apps::kExitError;
  }
  return apps::kExitOk;
}
