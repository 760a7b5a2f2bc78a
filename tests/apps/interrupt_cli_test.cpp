// Issue 41: every long command stops on Ctrl-C, SIGTERM and SIGHUP with
// 128 + the signal (130, 143, 129), nothing half-written and the previous
// output untouched; a second run into an output another run is writing is
// refused, naming it. The built `facadeslam` is started as a user's shell
// starts it (signals at their default disposition, not inherited as
// ignored the way a shell's background job would be) and signalled once it
// is in its long work.
#include <algorithm>
#include <chrono>
#include <csignal>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "tests/apps/cli_run.hpp"
#include "tests/semantics/synthetic_facades.hpp"
#include "tests/support/smooth_texture.hpp"
#include "tests/support/test_support.hpp"

extern char** environ;

namespace facadeslam {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

// A running `facadeslam ARGS`, stdout and stderr into files of `dir`.
class Process {
 public:
  Process(const std::vector<std::string>& arguments, const fs::path& dir, const std::string& name)
      : out_(dir / (name + ".out")), err_(dir / (name + ".err")) {
    std::vector<std::string> argv_text{FACADESLAM_BINARY, "-q"};
    argv_text.insert(argv_text.end(), arguments.begin(), arguments.end());
    std::vector<char*> argv;
    for (std::string& a : argv_text) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t files;
    posix_spawn_file_actions_init(&files);
    posix_spawn_file_actions_addopen(&files, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&files, 1, out_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(&files, 2, err_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawnattr_t attributes;
    posix_spawnattr_init(&attributes);
    sigset_t defaults, none;
    sigemptyset(&defaults);
    for (const int s : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&defaults, s);
    sigemptyset(&none);
    posix_spawnattr_setsigdefault(&attributes, &defaults);
    posix_spawnattr_setsigmask(&attributes, &none);
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK);
    EXPECT_EQ(posix_spawn(&pid_, argv[0], &files, &attributes, argv.data(), environ), 0);
    posix_spawn_file_actions_destroy(&files);
    posix_spawnattr_destroy(&attributes);
  }
  ~Process() {
    if (pid_ > 0 && running()) {
      ::kill(pid_, SIGKILL);
      ::waitpid(pid_, nullptr, 0);
    }
  }

  pid_t pid() const { return pid_; }
  bool running() {
    if (status_) return false;
    int status = 0;
    if (::waitpid(pid_, &status, WNOHANG) == pid_) status_ = status;
    return !status_;
  }
  // Seconds of CPU the process has used (user + system): past its checks
  // and start-up once this grows.
  double cpu_seconds() const {
    std::ifstream in("/proc/" + std::to_string(pid_) + "/stat");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto close = text.rfind(')');
    if (close == std::string::npos) return 0.0;
    std::istringstream fields(text.substr(close + 2));
    std::string field;
    double ticks = 0.0;
    for (int i = 3; i <= 15 && fields >> field; ++i)
      if (i == 14 || i == 15) ticks += std::stod(field);
    return ticks / static_cast<double>(::sysconf(_SC_CLK_TCK));
  }
  // The exit code (128 + n when it was killed by signal n without
  // handling it: what a shell shows, told apart by `killed`), waiting at
  // most `seconds`.
  int exit_code(double seconds, bool* killed = nullptr) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (running() && std::chrono::steady_clock::now() < end)
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    if (running()) {
      ADD_FAILURE() << "still running after " << seconds << " s";
      return -1;
    }
    if (killed) *killed = WIFSIGNALED(*status_);
    return WIFEXITED(*status_) ? WEXITSTATUS(*status_) : 128 + WTERMSIG(*status_);
  }
  std::string err() const { return test::read_file_text(err_); }
  std::string out() const { return test::read_file_text(out_); }

 private:
  fs::path out_, err_;
  pid_t pid_ = -1;
  std::optional<int> status_;
};

bool wait_until(const std::function<bool()>& condition, double seconds) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (!condition()) {
    if (std::chrono::steady_clock::now() > end) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return true;
}

// Every file below `folder` with its content.
std::map<std::string, std::string> snapshot(const fs::path& folder) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(folder))
    files[fs::relative(entry.path(), folder).string()] =
        entry.is_regular_file() ? test::read_file_text(entry.path()) : std::string("<folder>");
  return files;
}

std::vector<std::string> hidden_entries(const fs::path& folder) {
  std::vector<std::string> hidden;
  for (const auto& entry : fs::recursive_directory_iterator(folder))
    if (entry.path().filename().string().front() == '.') hidden.push_back(entry.path().string());
  return hidden;
}

class InterruptCli : public ::testing::Test {
 protected:
  test::TempDir dir_;
  fs::path logs() {
    fs::create_directories(dir_ / "logs");
    return dir_ / "logs";
  }
  // Signals `run` once it has used `cpu` seconds (its long work begun), then
  // returns its exit code.
  int stop(Process& run, int signal, double cpu) {
    EXPECT_TRUE(wait_until([&] { return !run.running() || run.cpu_seconds() >= cpu; }, 120)) << "never got busy";
    EXPECT_TRUE(run.running()) << "ended before the signal: make its work longer\n" << run.err();
    if (run.pid() > 0) ::kill(run.pid(), signal);  // never 0 or -1: those signal every process
    bool killed = false;
    const int code = run.exit_code(120, &killed);
    EXPECT_FALSE(killed) << "ended by the signal itself, not by handling it";
    return code;
  }
};

// A model and summary of an earlier run, as the output policy recognises them.
void write_earlier_model(const fs::path& model) {
  fs::create_directories(model.parent_path());
  fs::copy_file(test::source_dir() / "models" / "default.fsmodel", model);
  test::write_text(fs::path(model.string() + ".json"),
                   "{\"model\": \"m.fsmodel\", \"model_bytes\": 1, \"format_version\": 1, \"dataset\": \"d\", "
                   "\"split\": \"train.txt\"}\n");
}

TEST_F(InterruptCli, TrainStopsOnEachSignalLeavingTheEarlierModel) {
  // ~30 s of training uninterrupted on 2 cores; signalled after 1 s of CPU.
  semantics::test_util::write_synthetic_dataset(dir_ / "data", 12, 1, {320, 240});
  for (const auto& [signal, code] : {std::pair{SIGINT, 130}, std::pair{SIGTERM, 143}, std::pair{SIGHUP, 129}}) {
    SCOPED_TRACE(signal);
    const fs::path out = dir_ / ("models-" + std::to_string(signal));
    write_earlier_model(out / "m.fsmodel");
    const auto before = snapshot(out);
    Process run({"train", "--dataset", (dir_ / "data").string(), "--scales", "0.5,1,2", "--trees", "40", "--depth",
                 "30", "--out", (out / "m.fsmodel").string()},
                logs(), "train");
    EXPECT_EQ(stop(run, signal, 1.0), code) << run.err();
    EXPECT_EQ(snapshot(out), before) << "the earlier model was changed";
    EXPECT_THAT(hidden_entries(out), ::testing::IsEmpty());
  }
}

TEST_F(InterruptCli, EvaluateInvarianceStopsOnSigterm) {
  fs::create_directories(dir_ / "images");
  // ~45 s uninterrupted on 2 cores; signalled after 1 s of CPU.
  for (int i = 0; i < 2; ++i)
    cv::imwrite((dir_ / "images" / ("p" + std::to_string(i) + ".png")).string(),
                test::smooth_random_texture(320, 240, 10 + i));
  test::write_text(dir_ / "report.json",
                   "{\"images\": [], \"grid_step\": 9, \"margin\": 5, \"reference_keypoints\": 1}\n");
  const std::string before = test::read_file_text(dir_ / "report.json");
  Process run(
      {"evaluate", "invariance", "--images", (dir_ / "images").string(), "--json", (dir_ / "report.json").string()},
      logs(), "invariance");
  EXPECT_EQ(stop(run, SIGTERM, 1.0), 143) << run.err();
  EXPECT_EQ(test::read_file_text(dir_ / "report.json"), before);
  EXPECT_THAT(hidden_entries(dir_.path()), ::testing::IsEmpty());
}

TEST_F(InterruptCli, EvaluateLabelsStopsOnCtrlC) {
  // ~60 s uninterrupted on 2 cores; signalled after 1 s of CPU.
  semantics::test_util::write_synthetic_dataset(dir_ / "data", 12, 3, {320, 240});
  Process run({"evaluate", "labels", "--dataset", (dir_ / "data").string(), "--descriptor", "all", "--json",
               (dir_ / "labels.json").string()},
              logs(), "labels");
  EXPECT_EQ(stop(run, SIGINT, 1.0), 130) << run.err();
  EXPECT_FALSE(fs::exists(dir_ / "labels.json"));
  EXPECT_THAT(hidden_entries(dir_.path()), ::testing::IsEmpty());
}

// synth: a second run into the same --out is refused while the first
// renders; the first, hung up on, leaves the earlier sequence and no
// staging folder (SIGHUP was not handled: .NAME.tmp-PID stayed).
TEST_F(InterruptCli, SynthIsLockedAndStopsOnHangup) {
  const fs::path scene = test::source_dir() / "configs" / "scenes" / "demo.yaml";
  const fs::path out = dir_ / "runs" / "seq";
  Process earlier(
      {"synth", "--scene", scene.string(), "--frames", "2", "--resolution", "160x120", "--out", out.string()}, logs(),
      "earlier");
  ASSERT_EQ(earlier.exit_code(120), 0) << earlier.err();
  const auto before = snapshot(out);

  Process first(
      {"synth", "--scene", scene.string(), "--frames", "150", "--resolution", "320x240", "--out", out.string()}, logs(),
      "first");
  ASSERT_TRUE(wait_until([&] { return !first.running() || fs::exists(dir_ / "runs" / ".seq.lock"); }, 60));
  Process second(
      {"synth", "--scene", scene.string(), "--frames", "2", "--resolution", "160x120", "--out", out.string()}, logs(),
      "second");
  EXPECT_EQ(second.exit_code(60), 1) << second.err();
  const std::string refused = second.err();
  EXPECT_THAT(refused, HasSubstr("another facadeslam run (process " + std::to_string(first.pid()) +
                                 ") is writing this output now"));
  EXPECT_EQ(std::count(refused.begin(), refused.end(), '\n'), 1) << refused;

  EXPECT_EQ(stop(first, SIGHUP, 1.0), 129) << first.err();
  EXPECT_EQ(snapshot(out), before) << "the earlier sequence was changed";
  EXPECT_THAT(hidden_entries(dir_ / "runs"), ::testing::IsEmpty()) << "a staging folder or lock file was left";
}

// replay: the first SIGTERM finishes the map and writes complete outputs
// (report.json says interrupted), exit 143; the replay's own rendering
// folder outside --out is staged and moved into place with it.
TEST_F(InterruptCli, ReplayStopsOnSigtermWithCompleteOutputs) {
  const fs::path scene = test::source_dir() / "configs" / "scenes" / "demo.yaml";
  Process synth({"synth", "--scene", scene.string(), "--frames", "60", "--resolution", "320x240", "--out",
                 (dir_ / "seq").string()},
                logs(), "synth");
  ASSERT_EQ(synth.exit_code(300), 0) << synth.err();
  Process replay({"replay", (dir_ / "seq").string(), "--semantics", "off", "--loop", "100", "--render",
                  (dir_ / "ar").string(), "--render-every", "25", "--out", (dir_ / "out").string()},
                 logs(), "replay");
  EXPECT_EQ(stop(replay, SIGTERM, 2.0), 143) << replay.err();
  const std::string report = test::read_file_text(dir_ / "out" / "report.json");
  EXPECT_THAT(report, HasSubstr("\"interrupted\": true"));
  EXPECT_TRUE(fs::exists(dir_ / "ar" / "contact_sheet.png"));
  EXPECT_THAT(hidden_entries(dir_.path()), ::testing::IsEmpty());
}

}  // namespace
}  // namespace facadeslam
