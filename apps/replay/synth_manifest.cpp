#include "apps/replay/synth_manifest.hpp"

#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "core/util/error.hpp"
#include "sequences/list_file.hpp"
#include "sequences/open_sequence.hpp"

namespace facadeslam::apps {

void check_synth_manifest(const std::filesystem::path& sequence) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (detect_sequence_kind(sequence) != SequenceKind::tum_list) return;
  const fs::path list = fs::is_directory(sequence, ec) ? sequence / "rgb.txt" : sequence;
  const fs::path manifest = list.parent_path() / "synth.json";
  if (!fs::exists(manifest, ec)) return;
  nlohmann::json j;
  try {
    std::ifstream in(manifest);
    j = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception&) {
    fail_file(manifest, "not a synth manifest (expected the JSON object `facadeslam synth` writes)");
  }
  const auto frames = j.is_object() ? j.find("frames") : j.end();
  if (!j.is_object() || frames == j.end() || !frames->is_number_integer() || frames->get<long long>() < 1)
    fail_file(manifest, "not a synth manifest (expected a JSON object with \"frames\", a count of at least 1)");
  const std::size_t listed = read_list_file(list, "a TUM rgb.txt list").size();
  if (listed != frames->get<unsigned long long>()) {
    std::string what = "says ";
    what.append(std::to_string(frames->get<long long>())).append(" frames but ").append(list.string());
    what.append(" lists ").append(std::to_string(listed));
    fail_file(manifest, what.append(" (a folder edited or mixed from two synth runs? render it again)"));
  }
}

}  // namespace facadeslam::apps
