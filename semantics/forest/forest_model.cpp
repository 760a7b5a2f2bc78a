#include "semantics/forest/forest_model.hpp"

#include <algorithm>
#include <cctype>
#include <set>
#include <system_error>

#include <opencv2/core.hpp>

#include "core/map/semantic_classes.hpp"
#include "core/util/atomic_write.hpp"
#include "core/util/error.hpp"
#include "semantics/forest/fsmodel_format.hpp"
#include "semantics/forest/opencv_reason.hpp"
#include "semantics/text.hpp"

namespace facadeslam::semantics {
namespace {

constexpr const char* kFormat = "facadeslam-forest";
constexpr int kVersion = 1;

bool ends_with(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

std::string lower_file_name(const std::filesystem::path& path) {
  std::string name = path.filename().string();
  std::transform(name.begin(), name.end(), name.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return name;
}

bool is_fsmodel(const std::filesystem::path& path) { return ends_with(lower_file_name(path), ".fsmodel"); }

// FileStorage picks the syntax from the name, but the atomic writer's
// temporary name hides it (".model.yml.tmp12_0.gz"), so it is passed
// explicitly. Compression still follows the temporary name's ".gz".
int storage_format(const std::filesystem::path& path) {
  std::string name = lower_file_name(path);
  if (ends_with(name, ".gz")) name.resize(name.size() - 3);
  if (ends_with(name, ".yml") || ends_with(name, ".yaml")) return cv::FileStorage::FORMAT_YAML;
  if (ends_with(name, ".xml")) return cv::FileStorage::FORMAT_XML;
  if (ends_with(name, ".json")) return cv::FileStorage::FORMAT_JSON;
  fail_file(path,
            "a model file name must end in .fsmodel (recommended), or .yml, .yaml, .xml or .json, optionally + .gz");
}

void check_classes(const std::filesystem::path& path, const std::vector<ClassEntry>& classes,
                   const RandomForest& forest) {
  if (classes.empty()) fail_file(path, "the model has an empty class table (expected at least one class)");
  std::set<int> ids;
  for (const ClassEntry& c : classes) {
    if (c.id < 0 || c.name.empty()) fail_file(path, "class table entries need an id >= 0 and a name");
    if (!ids.insert(c.id).second) fail_file(path, cat("class id ", c.id, " appears twice in the class table"));
  }
  for (const int id : forest.classes())
    if (!ids.count(id))
      fail_file(path, cat("the forest predicts class id ", id, ", which the class table does not list"));
}

// Reads the header fields; every failure names the file and the key.
class ModelReader {
 public:
  ModelReader(const cv::FileNode& root, const std::filesystem::path& path) : root_(root), path_(path) {}

  [[noreturn]] void fail(const std::string& what) const { fail_file(path_, what); }

  cv::FileNode required(const std::string& key) const {
    const cv::FileNode node = root_[key];
    if (node.empty() || node.isNone()) {
      fail(cat("damaged or incomplete model file: missing key '", key, "' (expected a facadeslam forest model)"));
    }
    return node;
  }

  int integer(const cv::FileNode& node, const std::string& key) const {
    if (!node.isInt()) fail(cat("key '", key, "' must be an integer"));
    return static_cast<int>(node);
  }

  std::string text(const cv::FileNode& node, const std::string& key) const {
    if (!node.isString()) fail(cat("key '", key, "' must be a string"));
    return static_cast<std::string>(node);
  }

  int integer(const std::string& key) const { return integer(required(key), key); }
  std::string text(const std::string& key) const { return text(required(key), key); }

  std::vector<ClassEntry> classes() const {
    const cv::FileNode node = required("classes");
    if (!node.isSeq() || node.size() == 0)
      fail("key 'classes' must be a non-empty list of {id, name, rgb} (the class table)");
    std::vector<ClassEntry> table;
    for (const cv::FileNode& entry : node) {
      if (!entry.isMap()) fail("key 'classes' must hold {id, name, rgb} maps");
      ClassEntry c;
      c.id = integer(entry["id"], "classes/id");
      c.name = text(entry["name"], "classes/name");
      const cv::FileNode rgb = entry["rgb"];
      if (!rgb.isSeq() || rgb.size() != 3) fail("key 'classes/rgb' must be a list of three values 0..255");
      for (int k = 0; k < 3; ++k) {
        const int v = integer(rgb[k], "classes/rgb");
        if (v < 0 || v > 255) fail("key 'classes/rgb' must be a list of three values 0..255");
        c.rgb[k] = static_cast<uchar>(v);
      }
      table.push_back(std::move(c));
    }
    return table;
  }

 private:
  cv::FileNode root_;
  std::filesystem::path path_;
};

std::string class_table_text(const std::vector<ClassEntry>& classes) {
  std::string text;
  for (const ClassEntry& c : classes) {
    if (!text.empty()) text.append(", ");
    text.append(cat(c.id, ' ', c.name));
  }
  return text;
}

}  // namespace

void require_model_file_name(const std::filesystem::path& path) {
  if (!is_fsmodel(path)) storage_format(path);
}

const char* model_images_name(ModelImages images) {
  switch (images) {
    case ModelImages::colour: return "colour";
    case ModelImages::grey: return "grey";
    case ModelImages::unknown: break;
  }
  return "unknown";
}

std::vector<ClassEntry> labelmefacade_class_table() {
  std::vector<ClassEntry> table;
  for (const SemanticClass& c : kSemanticClasses)
    table.push_back({c.id, std::string(c.name), cv::Vec3b(c.r, c.g, c.b)});
  return table;
}

void save_forest_model(const std::filesystem::path& path, const ForestModel& model) {
  if (!model.forest.trained()) fail_file(path, "cannot save an untrained forest");
  if (model.descriptor.empty()) fail_file(path, "the model needs the descriptor name");
  check_classes(path, model.classes, model.forest);
  if (is_fsmodel(path)) {
    write_fsmodel(path, model);
    return;
  }
  const int format = storage_format(path);
  if (model.forest.model().empty())
    fail_file(path, "this forest was read from a .fsmodel file and can only be saved as .fsmodel");
  write_file_atomically(path, [&](const std::filesystem::path& tmp) {
    try {
      cv::FileStorage out(tmp.string(), cv::FileStorage::WRITE | format);
      if (!out.isOpened()) fail_file(path, "cannot open for writing");
      out << "format" << kFormat << "version" << kVersion;
      out << "descriptor" << model.descriptor << "descriptor_width" << model.descriptor_width();
      out << "genome" << model.genome.to_string();
      out << "classes"
          << "[";
      for (const ClassEntry& c : model.classes)
        out << "{"
            << "id" << c.id << "name" << c.name << "rgb"
            << "[:" << int{c.rgb[0]} << int{c.rgb[1]} << int{c.rgb[2]} << "]"
            << "}";
      out << "]";
      out << "forest"
          << "{";
      model.forest.model()->write(out);
      out << "}";
      out.release();
    } catch (const cv::Exception& e) {
      fail_file(path, cat("cannot write the forest model (", opencv_reason(e), ")"));
    }
  });
}

ForestModel load_forest_model(const std::filesystem::path& path) {
  if (is_fsmodel(path)) {
    ForestModel model = read_fsmodel(path);
    check_classes(path, model.classes, model.forest);
    return model;
  }
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    fail_file(path, "no such model file (expected a forest model written by facadeslam, e.g. model.yml.gz)");
  cv::FileStorage storage;
  try {
    storage.open(path.string(), cv::FileStorage::READ);
  } catch (const cv::Exception& e) {
    fail_file(path, cat("damaged or truncated model file, not readable as an OpenCV FileStorage document (",
                        opencv_reason(e), ")"));
  }
  if (!storage.isOpened() || !storage.root().isMap())
    fail_file(path, "not a readable model file (expected a facadeslam forest model, e.g. model.yml.gz)");

  const ModelReader in(storage.root(), path);
  const std::string format = in.text("format");
  if (format != kFormat)
    in.fail(cat("not a facadeslam forest model (format '", format, "', expected '", kFormat, "')"));
  const int version = in.integer("version");
  if (version != kVersion) in.fail(cat("model format version ", version, ", expected ", kVersion));

  ForestModel model;
  model.descriptor = in.text("descriptor");
  const int width = in.integer("descriptor_width");
  if (model.descriptor.empty() || width <= 0)
    in.fail("key 'descriptor' must name a descriptor and 'descriptor_width' be > 0");
  model.genome = Genome::parse(in.text("genome"), cat(path.string(), " (key 'genome')"));
  model.classes = in.classes();

  const cv::FileNode forest_node = in.required("forest");
  if (!forest_node.isMap()) in.fail("key 'forest' must hold the OpenCV random trees");
  try {
    cv::Ptr<cv::ml::RTrees> trees = cv::ml::RTrees::create();
    trees->read(forest_node);
    model.forest = RandomForest::from_model(trees);
    model.params.trees = model.forest.tree_count();
    model.params.max_depth = trees->getMaxDepth();
    model.params.split_variables = trees->getActiveVarCount();
    model.params.min_sample_count = trees->getMinSampleCount();
    model.params.seed = 0;  // not recorded in this format
  } catch (const cv::Exception& e) {
    in.fail(cat("damaged forest in the model file (", opencv_reason(e), ")"));
  } catch (const Error& e) {
    in.fail(cat("damaged forest in the model file: ", e.what()));
  }
  if (model.forest.descriptor_width() != width)
    in.fail(cat("the forest expects ", model.forest.descriptor_width(), " values per descriptor but the header says ",
                width, " (damaged file)"));
  check_classes(path, model.classes, model.forest);
  return model;
}

ForestModel load_forest_model(const std::filesystem::path& path, const ForestExpectation& expected) {
  ForestModel model = load_forest_model(path);
  check_forest_model(path, model, expected);
  return model;
}

void check_forest_model(const std::filesystem::path& path, const ForestModel& model,
                        const ForestExpectation& expected) {
  if (model.descriptor != expected.descriptor || model.descriptor_width() != expected.descriptor_width)
    fail_file(path, cat("the model was trained on descriptor '", model.descriptor, "' with ", model.descriptor_width(),
                        " values, expected '", expected.descriptor, "' with ", expected.descriptor_width, " values"));
  if (!(model.genome == expected.genome)) {
    int first = 0;
    while (first < Genome::kBits && model.genome.bit(first) == expected.genome.bit(first)) ++first;
    fail_file(path, cat("the model was trained with another genome than the expected one (first difference at bit ",
                        first, ", ", genome_bit_owner(first), ")"));
  }
  if (!expected.classes.empty() && model.classes != expected.classes)
    fail_file(path, cat("the model's class table (", class_table_text(model.classes), ") is not the expected one (",
                        class_table_text(expected.classes), ")"));
}

}  // namespace facadeslam::semantics
