#pragma once
// A scene file is validated through ConfigNode (unknown, missing, mistyped
// and out-of-range keys all fail naming the file and key), but a scene also
// holds lists of mappings (facades, trajectory segments, ...) and ConfigNode
// only reads mappings and lists of numbers. SceneYaml splits the named
// top-level lists off:
//   root()     a ConfigNode over the rest of the file, so that root().finish()
//              still reports unknown top-level keys;
//   list(key)  one ConfigNode per item, whose keys appear in messages as
//              "facades[2].width" — each must be finish()ed by the reader.
// (If ConfigNode gains list support, this helper can go.)
#include <filesystem>
#include <initializer_list>
#include <map>
#include <string>
#include <vector>

#include "core/config/config_node.hpp"

namespace facadeslam::synth {

class SceneYaml {
 public:
  // Error for a missing file, a YAML syntax error (with the line), a top
  // level that is not a mapping, or a list key holding anything other than a
  // list of mappings.
  SceneYaml(const std::filesystem::path& path, std::initializer_list<std::string> list_keys);

  const ConfigNode& root() const { return root_; }
  bool has_list(const std::string& key) const { return lists_.count(key) > 0; }
  // The items of a list key; empty when the key is absent.
  const std::vector<ConfigNode>& list(const std::string& key) const;

 private:
  void split_lists(const std::filesystem::path& path, std::initializer_list<std::string> list_keys);

  ConfigNode root_;
  std::map<std::string, std::vector<ConfigNode>> lists_;
  std::vector<ConfigNode> empty_;
};

}  // namespace facadeslam::synth
