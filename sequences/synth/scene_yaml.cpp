#include "sequences/synth/scene_yaml.hpp"

#include <yaml-cpp/yaml.h>

#include "core/util/error.hpp"

namespace facadeslam::synth {

SceneYaml::SceneYaml(const std::filesystem::path& path, std::initializer_list<std::string> list_keys)
    // Reading through ConfigNode first gives its messages for a missing
    // file, a syntax error and a non-mapping top level.
    : root_(ConfigNode::load_file(path)) {
  // The raw yaml-cpp work below (re-dumping parts of a document that
  // ConfigNode has accepted) should not fail; if a hostile file finds a way,
  // it is still one line naming the file.
  try {
    split_lists(path, list_keys);
  } catch (const YAML::Exception& e) {
    throw Error(path.string() + ": not valid YAML for a scene (line " + std::to_string(e.mark.line + 1) + ": " +
                e.msg + ")");
  }
}

void SceneYaml::split_lists(const std::filesystem::path& path, std::initializer_list<std::string> list_keys) {
  const YAML::Node document = YAML::LoadFile(path.string());
  YAML::Node rest = YAML::Clone(document);
  for (const std::string& key : list_keys) rest.remove(key);
  root_ = ConfigNode::parse_string(YAML::Dump(rest), path.string());

  for (const std::string& key : list_keys) {
    const YAML::Node value = document[key];
    if (!value) continue;
    if (!value.IsSequence())
      root_.fail(key, "a list of mappings (lines starting with '- ')",
                 value.IsMap() ? "a mapping" : value.IsScalar() ? value.Scalar() : "nothing");
    std::vector<ConfigNode>& items = lists_[key];
    for (std::size_t i = 0; i < value.size(); ++i) {
      // Wrapped under "key[i]" so that messages name the item.
      const std::string item_key = key + "[" + std::to_string(i) + "]";
      YAML::Node wrapper(YAML::NodeType::Map);
      wrapper[item_key] = value[i];
      items.push_back(ConfigNode::parse_string(YAML::Dump(wrapper), path.string()).child(item_key));
    }
  }
}

const std::vector<ConfigNode>& SceneYaml::list(const std::string& key) const {
  const auto it = lists_.find(key);
  return it == lists_.end() ? empty_ : it->second;
}

}  // namespace facadeslam::synth
