#include "core/util/output_policy.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <system_error>
#include <utility>

#include <nlohmann/json.hpp>

#include "core/util/error.hpp"
#include "core/util/path_checks.hpp"
#include "core/util/png_signature.hpp"

namespace facadeslam {
namespace {

namespace fs = std::filesystem;

// Enough of a file to recognise it; JSON reports are parsed whole up to a
// size no report of ours reaches (a soak's report.json is ~1 MB).
constexpr std::size_t kHeadBytes = 64 * 1024;
constexpr std::uintmax_t kLargestJson = 256ull * 1024 * 1024;

std::string file_head(const fs::path& path, std::size_t bytes) {
  std::ifstream in(path, std::ios::binary);
  std::string head(bytes, '\0');
  in.read(head.data(), static_cast<std::streamsize>(bytes));
  head.resize(in ? bytes : static_cast<std::size_t>(std::max<std::streamsize>(0, in.gcount())));
  return head;
}

// `name` matches `pattern`, in which one '*' stands for any characters.
bool matches(const std::string& name, const std::string& pattern) {
  const auto star = pattern.find('*');
  if (star == std::string::npos) return name == pattern;
  const std::string before = pattern.substr(0, star), after = pattern.substr(star + 1);
  return name.size() >= before.size() + after.size() && name.compare(0, before.size(), before) == 0 &&
         name.compare(name.size() - after.size(), after.size(), after) == 0;
}

const OutputFolderEntry* entry_for(const OutputFolderLayout& layout, const std::string& name) {
  for (const OutputFolderEntry& entry : layout.entries)
    if (matches(name, entry.pattern)) return &entry;
  return nullptr;
}

std::string what_entry_holds(const OutputFolderEntry& entry) {
  return entry.folder ? entry.folder->description : entry.file.description;
}

// "'name'" for messages, joined with the folders above it.
std::string shown(const fs::path& relative) { return quoted_for_message(relative.generic_string()); }

std::string foreign_below(const fs::path& folder, const fs::path& relative, const OutputFolderLayout& layout,
                          int depth) {
  std::error_code ec;
  fs::directory_iterator it(folder, ec), end;
  if (ec) return shown(relative) + ", which cannot be listed (" + ec.message() + ")";
  for (; it != end; it.increment(ec)) {
    if (ec) return shown(relative) + ", which cannot be listed (" + ec.message() + ")";
    const fs::path path = it->path();
    const fs::path entry_relative = relative / path.filename();
    const OutputFolderEntry* entry = entry_for(layout, path.filename().string());
    if (!entry) return shown(entry_relative) + ", which " + layout.description + " never holds";
    const fs::file_status status = fs::symlink_status(path, ec);
    if (ec || fs::is_symlink(status)) return shown(entry_relative) + ", a symbolic link, which no output is";
    if (entry->folder) {
      if (!fs::is_directory(status)) return shown(entry_relative) + ", which is not a folder";
      if (depth > 8) return shown(entry_relative) + ", nested too deep";
      if (std::string below = foreign_below(path, entry_relative, *entry->folder, depth + 1); !below.empty())
        return below;
    } else if (!fs::is_regular_file(status) || !entry->file.recognises(path)) {
      return shown(entry_relative) + ", which is not " + entry->file.description;
    }
  }
  return {};
}

bool same_kind(const OutputFileKind& a, const OutputFileKind& b) { return a.description == b.description; }

}  // namespace

OutputFileKind file_starting_with(std::string description, std::string prefix) {
  return {std::move(description),
          [prefix = std::move(prefix)](const fs::path& path) { return file_head(path, prefix.size()) == prefix; }};
}

OutputFileKind png_file(std::string description) {
  return {std::move(description), [](const fs::path& path) { return is_signed_png(path); }};
}

OutputFileKind json_object_with_keys(std::string description, std::vector<std::string> keys) {
  return {std::move(description), [keys = std::move(keys)](const fs::path& path) {
            std::error_code ec;
            const std::uintmax_t size = fs::file_size(path, ec);
            if (ec || size > kLargestJson) return false;
            const nlohmann::json json = nlohmann::json::parse(file_head(path, static_cast<std::size_t>(size)), nullptr,
                                                              /*allow_exceptions=*/false);
            if (!json.is_object()) return false;
            return std::all_of(keys.begin(), keys.end(), [&](const std::string& key) { return json.contains(key); });
          }};
}

OutputFileKind text_with_line(std::string description, std::string line_prefix) {
  return {std::move(description), [line_prefix = std::move(line_prefix)](const fs::path& path) {
            const std::string head = file_head(path, kHeadBytes);
            for (std::size_t at = 0; at < head.size();) {
              if (head.compare(at, line_prefix.size(), line_prefix) == 0) return true;
              const auto next = head.find('\n', at);
              if (next == std::string::npos) break;
              at = next + 1;
            }
            return false;
          }};
}

OutputFileKind numbered_lines(std::string description) {
  return {std::move(description), [](const fs::path& path) {
            const std::string head = file_head(path, kHeadBytes);
            if (head.find('\0') != std::string::npos) return false;
            std::size_t at = 0;
            while (at < head.size()) {
              auto end = head.find('\n', at);
              const bool last = end == std::string::npos;
              if (last) end = head.size();
              const std::string line = head.substr(at, end - at);
              at = end + 1;
              const auto first = line.find_first_not_of(" \t\r");
              if (first == std::string::npos || line[first] == '#') continue;
              // The last line of a file longer than the head may be cut.
              if (last && head.size() == kHeadBytes) break;
              char* number_end = nullptr;
              const char* start = line.c_str() + first;
              std::strtod(start, &number_end);
              if (number_end == start) return false;
            }
            return true;
          }};
}

OutputFileKind text_file(std::string description) {
  return {std::move(description),
          [](const fs::path& path) { return file_head(path, kHeadBytes).find('\0') == std::string::npos; }};
}

OutputFileKind any_of(std::string description, std::vector<OutputFileKind> kinds) {
  return {std::move(description), [kinds = std::move(kinds)](const fs::path& path) {
            return std::any_of(kinds.begin(), kinds.end(), [&](const OutputFileKind& k) { return k.recognises(path); });
          }};
}

OutputFolderEntry file_entry(std::string pattern, OutputFileKind kind, bool every_run) {
  return {std::move(pattern), std::move(kind), nullptr, every_run};
}

OutputFolderEntry folder_entry(std::string pattern, std::shared_ptr<const OutputFolderLayout> layout, bool every_run) {
  return {std::move(pattern), {}, std::move(layout), every_run};
}

std::string foreign_entry(const fs::path& folder, const OutputFolderLayout& layout) {
  if (!path_exists(folder)) return {};  // nothing there to lose
  return foreign_below(folder, {}, layout, 0);
}

fs::path resolved_path(const fs::path& path) {
  std::error_code ec;
  fs::path absolute = fs::absolute(path, ec);
  if (ec) absolute = path;
  fs::path resolved = fs::weakly_canonical(absolute, ec);
  return ec ? absolute.lexically_normal() : resolved.lexically_normal();
}

bool lies_within(const fs::path& path, const fs::path& folder) {
  const fs::path p = resolved_path(path), f = resolved_path(folder);
  auto pi = p.begin();
  for (auto fi = f.begin(); fi != f.end(); ++fi, ++pi) {
    if (fi->empty() && std::next(fi) == f.end()) break;  // a trailing separator
    if (pi == p.end() || *pi != *fi) return false;
  }
  return true;
}

void OutputPlan::input(const fs::path& path, std::string option) {
  if (!path.empty()) inputs_.push_back({path, resolved_path(path), std::move(option), false});
}

void OutputPlan::input_folder_read_whole(const fs::path& folder, std::string option) {
  if (!folder.empty()) inputs_.push_back({folder, resolved_path(folder), std::move(option), true});
}

void OutputPlan::output_file(const fs::path& path, std::string option, OutputFileKind kind) {
  if (!path.empty()) outputs_.push_back({path, resolved_path(path), std::move(option), std::move(kind), nullptr});
}

void OutputPlan::output_folder(const fs::path& path, std::string option,
                               std::shared_ptr<const OutputFolderLayout> layout) {
  if (!path.empty()) outputs_.push_back({path, resolved_path(path), std::move(option), {}, std::move(layout)});
}

void OutputPlan::check_against_inputs(const Output& output) const {
  // The most precise message first: the output is an input, then it holds
  // one, then it lies among inputs.
  for (const Input& input : inputs_)
    if (output.resolved == input.resolved)
      fail_file(output.path, output.option + " is also the input " + input.option + ": refusing to overwrite it");
  for (const Input& input : inputs_)
    if (output.layout && lies_within(input.resolved, output.resolved))
      fail_file(output.path, output.option + " holds the input " + input.option + " (" + input.path.string() +
                                 "), and a run replaces the folder as a whole: give another output folder");
  for (const Input& input : inputs_)
    if (!output.layout && input.read_whole && output.resolved.parent_path() == input.resolved)
      fail_file(output.path, output.option + " lies in " + input.option +
                                 ", every file of which is read as input: write it elsewhere");
}

void OutputPlan::check_against_outputs(const Output& output, std::size_t index) const {
  for (std::size_t j = 0; j < outputs_.size(); ++j) {
    const Output& other = outputs_[j];
    if (j == index) continue;
    if (output.resolved == other.resolved) {
      if (j < index) fail_file(output.path, output.option + " is the same path as " + other.option);
      continue;
    }
    if (!other.layout || !lies_within(output.resolved, other.resolved)) continue;
    // Inside another output folder: only under a name that folder's command
    // leaves free for it, else the two would collide or the next run would
    // find a file it never writes there.
    const fs::path relative = output.resolved.lexically_relative(other.resolved);
    const OutputFolderLayout* layout = other.layout.get();
    const OutputFolderEntry* entry = nullptr;
    for (auto part = relative.begin(); part != relative.end(); ++part) {
      entry = layout ? entry_for(*layout, part->string()) : nullptr;
      const bool last = std::next(part) == relative.end();
      if (!entry || (!last && !entry->folder)) {
        fail_file(output.path, output.option + " lies in " + other.option + " under a name " +
                                   other.layout->description + " never holds: write it elsewhere");
      }
      if (!last) layout = entry->folder.get();
    }
    const bool kind_fits =
        output.layout ? entry->folder == output.layout : !entry->folder && same_kind(entry->file, output.kind);
    if (entry->every_run || !kind_fits)
      fail_file(output.path, output.option + " is where " + other.option + " puts " + what_entry_holds(*entry) +
                                 ": give another name");
  }
}

void OutputPlan::check_existing(const Output& output) {
  std::error_code ec;
  const fs::file_status status = fs::status(output.path, ec);
  if (!fs::exists(status)) {
    // A link to nothing: writing would replace the link, not make its target.
    if (fs::is_symlink(fs::symlink_status(output.path, ec)))
      fail_file(output.path, output.option + " is a symbolic link to nothing: refusing to replace it");
    return;
  }
  if (output.layout) {
    if (!fs::is_directory(status)) fail_file(output.path, output.option + " is an output folder, but it is a file");
    if (const std::string foreign = foreign_entry(output.path, *output.layout); !foreign.empty())
      fail_file(output.path, output.option + " holds " + foreign +
                                 "; a run replaces the folder as a whole, so it "
                                 "must be new, empty or " +
                                 output.layout->description);
    return;
  }
  if (fs::is_directory(status)) fail_file(output.path, output.option + " is a folder (expected an output file name)");
  if (!fs::is_regular_file(status))
    fail_file(output.path, output.option + " " + describe_path(output.path) + " (expected an output file name)");
  if (!output.kind.recognises(output.path))
    fail_file(output.path, output.option + " would replace a file that is not " + output.kind.description +
                               " (a file of yours?): refusing; remove it or give another name");
}

void OutputPlan::check() const {
  for (std::size_t i = 0; i < outputs_.size(); ++i) {
    const Output& output = outputs_[i];
    check_against_inputs(output);
    check_against_outputs(output, i);
    // Inside another output folder it is that folder's entry (checked with it).
    const bool inside_other = std::any_of(outputs_.begin(), outputs_.end(), [&](const Output& other) {
      return &other != &output && other.layout && output.resolved != other.resolved &&
             lies_within(output.resolved, other.resolved);
    });
    if (!inside_other) check_existing(output);
  }
}

}  // namespace facadeslam
