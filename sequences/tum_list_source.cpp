#include "sequences/tum_list_source.hpp"

#include <string>
#include <vector>

#include "core/util/error.hpp"
#include "core/util/input_confinement.hpp"
#include "core/util/path_checks.hpp"
#include "sequences/list_file.hpp"

namespace facadeslam {
namespace {

namespace fs = std::filesystem;

constexpr const char* kExpectedLines = "lines 'timestamp relative/path.png'";

std::vector<ImageEntry> list_entries(const fs::path& list_file, const SequenceOptions& options) {
  validate(options);
  if (!path_exists(list_file))
    fail_file(list_file, std::string("no such file (expected a TUM rgb.txt list of ") + kExpectedLines + ")");
  if (!is_readable_file(list_file))
    fail_file(list_file, describe_path(list_file) + " (expected a TUM rgb.txt list of " + kExpectedLines + ")");
  const auto lines = read_list_file(list_file, std::string("a TUM rgb.txt list of ") + kExpectedLines);
  if (lines.empty()) fail_file(list_file, std::string("no images found (expected ") + kExpectedLines + ")");

  const fs::path base = list_file.parent_path();
  std::vector<ImageEntry> all;
  all.reserve(lines.size());
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const ListLine& line = lines[i];
    if (line.fields.size() != 2)
      fail_line(list_file, line.number,
                "found " + std::to_string(line.fields.size()) + " fields (expected 'timestamp relative/path.png')");
    const double timestamp = parse_timestamp(line.fields[0], list_file, line.number);
    if (i > 0) require_increasing(all.back().timestamp, lines[i - 1].number, timestamp, line.number, list_file);
    const fs::path listed(line.fields[1]);
    const fs::path image = listed.is_absolute() ? listed : base / listed;
    // Inside the list's folder (input_confinement.hpp): a list from
    // elsewhere must not make the replay read /etc/passwd or ../../...
    require_confined(image, base.empty() ? fs::path(".") : base, list_file, line.number, line.fields[1]);
    if (!is_readable_file(image))
      fail_line(list_file, line.number,
                "listed image " + image.string() + " " + describe_path(image) +
                    " (expected an image file; paths relative to " + (base.empty() ? std::string(".") : base.string()) +
                    ")");
    all.push_back({i, timestamp, image});
  }
  return select_entries(std::move(all), options, list_file);
}

}  // namespace

TumListSource::TumListSource(const fs::path& list_file, const SequenceOptions& options)
    : ImageListSource(list_entries(list_file, options), options.on_corrupt, "TUM list " + list_file.string()) {}

}  // namespace facadeslam
