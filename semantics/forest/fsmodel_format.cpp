#include "semantics/forest/fsmodel_format.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <system_error>

#include "core/util/atomic_write.hpp"
#include "core/util/byte_stream.hpp"
#include "core/util/error.hpp"
#include "semantics/forest/zlib_codec.hpp"
#include "semantics/text.hpp"

namespace facadeslam::semantics {
namespace {

constexpr std::array<char, 8> kMagic{'F', 'S', 'M', 'O', 'D', 'E', 'L', '\0'};
constexpr std::size_t kHeaderBytes = 32;
// Sanity bounds for counts read from a file (a damaged count must not
// allocate gigabytes): far above any real forest.
constexpr std::size_t kMaxPayload = std::size_t{1} << 30;
constexpr std::size_t kMaxNodes = std::size_t{1} << 28;
constexpr std::size_t kMaxItems = std::size_t{1} << 16;

std::vector<unsigned char> encode_payload(const ForestModel& model) {
  const RandomForest& forest = model.forest;
  ByteWriter w;
  w.put_text(model.descriptor);
  w.put_text(model.genome.to_string());
  w.put(static_cast<std::uint8_t>(model.images));
  w.put(static_cast<std::uint32_t>(model.classes.size()));
  for (const ClassEntry& c : model.classes) {
    w.put(static_cast<std::int32_t>(c.id));
    w.put_text(c.name);
    for (int k = 0; k < 3; ++k) w.put(static_cast<std::uint8_t>(c.rgb[k]));
  }
  w.put(static_cast<std::int32_t>(model.params.trees));
  w.put(static_cast<std::int32_t>(model.params.max_depth));
  w.put(static_cast<std::int32_t>(model.params.split_variables));
  w.put(static_cast<std::int32_t>(model.params.min_sample_count));
  w.put(static_cast<std::uint64_t>(model.params.seed));

  w.put(static_cast<std::int32_t>(forest.descriptor_width()));
  w.put(static_cast<std::uint32_t>(forest.classes().size()));
  for (const int id : forest.classes()) w.put(static_cast<std::int32_t>(id));
  w.put(static_cast<std::uint32_t>(forest.roots().size()));
  for (const int r : forest.roots()) w.put(static_cast<std::int32_t>(r));
  const std::vector<RandomForest::Node>& nodes = forest.nodes();
  w.put(static_cast<std::uint32_t>(nodes.size()));
  for (const RandomForest::Node& n : nodes) w.put(static_cast<std::int16_t>(n.var >= 0 ? n.var : -1 - n.leaf_class));
  for (const RandomForest::Node& n : nodes)
    if (n.var >= 0) w.put(n.threshold);
  for (std::size_t i = 0; i < nodes.size(); ++i)
    if (nodes[i].var >= 0) w.put(static_cast<std::uint32_t>(static_cast<std::size_t>(nodes[i].low) - i));
  for (std::size_t i = 0; i < nodes.size(); ++i)
    if (nodes[i].var >= 0) w.put(static_cast<std::uint32_t>(static_cast<std::size_t>(nodes[i].high) - i));
  return {w.bytes().begin(), w.bytes().end()};
}

ForestModel decode_payload(const std::vector<unsigned char>& payload, std::uint32_t version,
                           const std::filesystem::path& path) {
  ByteReader r({reinterpret_cast<const char*>(payload.data()), payload.size()}, path, "damaged model file");
  ForestModel model;
  model.descriptor = r.text("the descriptor name", 64);
  model.genome = Genome::parse(r.text("the genome", 1024), cat(path.string(), " (genome)"));
  if (version >= 2) {
    const auto images = r.get<std::uint8_t>("the kind of training images");
    if (images != 0 && images != 1 && images != 255)
      fail_file(path, cat("damaged model file: training images of kind ", int{images},
                          ", expected 0 (colour), 1 (grey) or 255 (unknown)"));
    model.images = static_cast<ModelImages>(images);
  }
  const std::size_t class_count = r.count("the class count", 11, kMaxItems);
  for (std::size_t k = 0; k < class_count; ++k) {
    ClassEntry c;
    c.id = r.get<std::int32_t>("a class id");
    c.name = r.text("a class name", 256);
    for (int i = 0; i < 3; ++i) c.rgb[i] = r.get<std::uint8_t>("a class colour");
    model.classes.push_back(std::move(c));
  }
  model.params.trees = r.get<std::int32_t>("the forest settings");
  model.params.max_depth = r.get<std::int32_t>("the forest settings");
  model.params.split_variables = r.get<std::int32_t>("the forest settings");
  model.params.min_sample_count = r.get<std::int32_t>("the forest settings");
  model.params.seed = r.get<std::uint64_t>("the forest settings");

  const int width = r.get<std::int32_t>("the descriptor width");
  std::vector<int> classes(r.count("the forest's class count", 4, kMaxItems));
  for (int& id : classes) id = r.get<std::int32_t>("the forest's class ids");
  std::vector<int> roots(r.count("the tree count", 4, kMaxItems));
  for (int& root : roots) root = r.get<std::int32_t>("the tree roots");
  std::vector<RandomForest::Node> nodes(r.count("the node count", 2, kMaxNodes));
  std::vector<std::size_t> splits;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const int v = r.get<std::int16_t>("the node variables");
    if (v >= 0) {
      nodes[i].var = v;
      splits.push_back(i);
    } else {
      nodes[i].leaf_class = -1 - v;
    }
  }
  for (const std::size_t i : splits) nodes[i].threshold = r.get<float>("the split thresholds");
  // Offsets past the array wrap to values that from_nodes() rejects.
  for (const std::size_t i : splits) nodes[i].low = static_cast<int>(i + r.get<std::uint32_t>("the low children"));
  for (const std::size_t i : splits) nodes[i].high = static_cast<int>(i + r.get<std::uint32_t>("the high children"));
  if (!r.at_end()) fail_file(path, "damaged model file: bytes left over after the forest");
  try {
    model.forest = RandomForest::from_nodes(width, std::move(classes), std::move(nodes), std::move(roots));
  } catch (const Error& e) {
    fail_file(path, cat("damaged forest in the model file: ", e.what()));
  }
  return model;
}

std::vector<unsigned char> read_all(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    fail_file(path, "no such model file (expected a .fsmodel file written by `facadeslam train`)");
  std::ifstream in(path, std::ios::binary);
  if (!in) fail_file(path, "cannot open the model file for reading");
  std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) fail_file(path, "read error");
  return bytes;
}

}  // namespace

void write_fsmodel(const std::filesystem::path& path, const ForestModel& model) {
  if (model.descriptor_width() > std::numeric_limits<std::int16_t>::max() ||
      static_cast<int>(model.forest.classes().size()) > std::numeric_limits<std::int16_t>::max())
    fail_file(path, "the forest is too wide for the .fsmodel format (at most 32767 values and classes)");
  const std::vector<unsigned char> payload = encode_payload(model);
  std::vector<unsigned char> compressed;
  try {
    compressed = deflate_bytes(payload);
  } catch (const Error& e) {
    fail_file(path, e.what());
  }
  ByteWriter header;
  header.put_bytes(kMagic.data(), kMagic.size());
  header.put(static_cast<std::uint32_t>(kFsmodelVersion));
  header.put(static_cast<std::uint64_t>(payload.size()));
  header.put(crc32_of(payload));
  header.put(static_cast<std::uint64_t>(compressed.size()));
  write_atomically(
      path,
      [&](std::ostream& out) {
        out.write(header.bytes().data(), static_cast<std::streamsize>(header.bytes().size()));
        out.write(reinterpret_cast<const char*>(compressed.data()), static_cast<std::streamsize>(compressed.size()));
      },
      true);
}

ForestModel read_fsmodel(const std::filesystem::path& path) {
  const std::vector<unsigned char> file = read_all(path);
  if (file.size() < kHeaderBytes || !std::equal(kMagic.begin(), kMagic.end(), file.begin()))
    fail_file(path, cat("not a facadeslam model file (expected a .fsmodel file starting with \"FSMODEL\", ",
                        "written by `facadeslam train`)"));
  ByteReader header({reinterpret_cast<const char*>(file.data()), kHeaderBytes}, path, "damaged model file");
  header.take(kMagic.size(), "the magic");
  const auto version = header.get<std::uint32_t>("the format version");
  // Format 1 differs only by not saying what images the forest learnt from.
  if (version != 1 && version != kFsmodelVersion)
    fail_file(path, cat("model format version ", version, ", expected 1 or ", kFsmodelVersion,
                        " (retrain it with this facadeslam: `facadeslam train`)"));
  const auto size = header.get<std::uint64_t>("the payload size");
  const auto crc = header.get<std::uint32_t>("the checksum");
  const auto compressed_size = header.get<std::uint64_t>("the compressed size");
  if (compressed_size != file.size() - kHeaderBytes)
    fail_file(path, cat("truncated or damaged model file: the header announces ", compressed_size,
                        " compressed bytes, the file holds ", file.size() - kHeaderBytes));
  if (size > kMaxPayload) fail_file(path, cat("damaged model file: payload size ", size, " is implausible"));
  std::vector<unsigned char> payload;
  try {
    payload = inflate_bytes(std::vector<unsigned char>(file.begin() + kHeaderBytes, file.end()), size);
  } catch (const Error& e) {
    fail_file(path, cat("damaged model file: ", e.what()));
  }
  if (crc32_of(payload) != crc) fail_file(path, "damaged model file: the checksum of the forest does not match");
  return decode_payload(payload, version, path);
}

}  // namespace facadeslam::semantics
