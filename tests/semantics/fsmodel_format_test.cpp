// The .fsmodel file: exact round trip, and every way a file can be wrong
// (short, damaged, foreign, another version, another class table) fails
// with the file named. Also the flat-node forest's own consistency checks.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>

#include <opencv2/core.hpp>

#include "core/util/error.hpp"
#include "semantics/forest/forest_model.hpp"
#include "semantics/forest/fsmodel_format.hpp"
#include "semantics/forest/random_forest.hpp"
#include "semantics/forest/zlib_codec.hpp"
#include "tests/semantics/forest_test_data.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam::semantics {
namespace {

using test_util::read_bytes;
using test_util::write_bytes;
using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

class FsmodelFile : public ::testing::Test {
 protected:
  void SetUp() override {
    test_util::blobs(100, 1, train_x, train_y);
    test_util::blobs(50, 2, test_x, test_y);
    model.params = test_util::small_forest();
    model.params.seed = 7;
    model.forest = RandomForest::train(train_x, train_y, model.params);
    model.descriptor = "edd";
    model.genome = Genome::thesis_best();
    model.classes = labelmefacade_class_table();
    model.images = ModelImages::grey;
    save_forest_model(path, model);
    bytes = read_bytes(path);
  }
  // Expect load_forest_model(path) to fail naming the file and `what`.
  void expect_rejected(const std::string& what) {
    EXPECT_THAT([&] { load_forest_model(path); },
                ThrowsMessage<Error>(AllOf(HasSubstr(path.string()), HasSubstr(what))));
  }
  test::TempDir dir;
  std::filesystem::path path = dir / "model.fsmodel";
  cv::Mat train_x, test_x;
  std::vector<int> train_y, test_y;
  ForestModel model;
  std::string bytes;
};

TEST_F(FsmodelFile, RoundTripIsExact) {
  ASSERT_GE(bytes.size(), 32u);
  EXPECT_EQ(bytes.substr(0, 8), std::string("FSMODEL\0", 8));
  int files = 0;  // no temporary file left beside it
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir.path())) ++files;
  EXPECT_EQ(files, 1);

  const ForestModel loaded = load_forest_model(path);
  EXPECT_EQ(loaded.descriptor, "edd");
  EXPECT_EQ(loaded.genome, Genome::thesis_best());
  EXPECT_EQ(loaded.classes, labelmefacade_class_table());
  EXPECT_EQ(loaded.images, ModelImages::grey);
  EXPECT_EQ(loaded.params.trees, 15);
  EXPECT_EQ(loaded.params.max_depth, 8);
  EXPECT_EQ(loaded.params.split_variables, 2);
  EXPECT_EQ(loaded.params.min_sample_count, 2);
  EXPECT_EQ(loaded.params.seed, 7u);
  EXPECT_EQ(loaded.descriptor_width(), 3);
  EXPECT_EQ(loaded.forest.classes(), model.forest.classes());
  EXPECT_EQ(loaded.forest.roots(), model.forest.roots());
  EXPECT_EQ(loaded.forest.nodes(), model.forest.nodes());  // thresholds bit for bit
  EXPECT_TRUE(loaded.forest.model().empty());
  // The same votes on every row, so the same labels and vote shares.
  EXPECT_EQ(cv::norm(loaded.forest.votes(test_x), model.forest.votes(test_x), cv::NORM_INF), 0.0);
  // Saving it again gives the same bytes.
  save_forest_model(dir / "again.fsmodel", loaded);
  EXPECT_EQ(read_bytes(dir / "again.fsmodel"), bytes);
}

TEST_F(FsmodelFile, SmallerThanOpenCvsOwnFormat) {
  save_forest_model(dir / "model.yml.gz", model);
  EXPECT_LT(bytes.size(), std::filesystem::file_size(dir / "model.yml.gz") / 2);
}

TEST_F(FsmodelFile, TruncatedFilesAreRejected) {
  for (const std::size_t keep :
       {std::size_t{0}, std::size_t{10}, std::size_t{31}, std::size_t{32}, bytes.size() / 2, bytes.size() - 1}) {
    write_bytes(path, bytes.substr(0, keep));
    SCOPED_TRACE(keep);
    expect_rejected(keep < 32 ? "not a facadeslam model file" : "truncated");
  }
}

TEST_F(FsmodelFile, DamagedPayloadIsRejected) {
  // Any flipped byte of the compressed payload: zlib or the CRC notices.
  for (const std::size_t at : {std::size_t{32}, std::size_t{40}, bytes.size() / 2, bytes.size() - 5}) {
    std::string damaged = bytes;
    damaged[at] = static_cast<char>(damaged[at] ^ 0x5a);
    write_bytes(path, damaged);
    SCOPED_TRACE(at);
    expect_rejected("damaged model file");
  }
  // A wrong CRC in the header.
  std::string damaged = bytes;
  damaged[20] = static_cast<char>(damaged[20] ^ 1);
  write_bytes(path, damaged);
  expect_rejected("checksum");
}

// Whatever single byte is damaged, header or payload, loading fails with
// the file named (never a crash, never a silently different forest).
TEST_F(FsmodelFile, EveryDamagedByteIsDetected) {
  for (std::size_t at = 0; at < bytes.size(); ++at) {
    std::string damaged = bytes;
    damaged[at] = static_cast<char>(damaged[at] ^ 0xff);
    write_bytes(path, damaged);
    try {
      load_forest_model(path);
      ADD_FAILURE() << "byte " << at << " of " << bytes.size() << " damaged, yet the file loaded";
    } catch (const Error& e) {
      EXPECT_THAT(e.what(), HasSubstr(path.string())) << "byte " << at;
    }
  }
}

// A payload with a valid checksum whose node count is huge (a writer bug,
// or a crafted file) fails before allocating for it.
TEST_F(FsmodelFile, ImplausibleCountsFailBeforeAllocating) {
  std::uint64_t size = 0, compressed_size = 0;
  std::memcpy(&size, bytes.data() + 12, 8);
  const std::vector<unsigned char> compressed(bytes.begin() + 32, bytes.end());
  std::vector<unsigned char> payload = inflate_bytes(compressed, size);
  // The node count sits just before the node columns (fsmodel_format.hpp):
  // 2 bytes per node, 12 per split node.
  std::size_t splits = 0;
  for (const RandomForest::Node& n : model.forest.nodes()) splits += n.var >= 0 ? 1 : 0;
  const std::size_t at = payload.size() - 2 * model.forest.nodes().size() - 12 * splits - 4;
  std::uint32_t count = 0;
  std::memcpy(&count, payload.data() + at, 4);
  ASSERT_EQ(count, model.forest.nodes().size());
  count = 0x0fffffff;  // 268 million nodes: gigabytes if allocated
  std::memcpy(payload.data() + at, &count, 4);

  const std::vector<unsigned char> recompressed = deflate_bytes(payload);
  const std::uint32_t crc = crc32_of(payload);
  compressed_size = recompressed.size();
  std::string crafted = bytes.substr(0, 32);
  std::memcpy(crafted.data() + 20, &crc, 4);
  std::memcpy(crafted.data() + 24, &compressed_size, 8);
  crafted.append(recompressed.begin(), recompressed.end());
  write_bytes(path, crafted);
  expect_rejected("the node count is 268435455 but only");
}

TEST_F(FsmodelFile, ForeignFilesAndOtherVersionsAreRejected) {
  write_bytes(path, "%YAML:1.0\n---\nformat: facadeslam-forest\nversion: 1\n");
  expect_rejected("not a facadeslam model file");
  std::string v2 = bytes;
  const std::uint32_t version = 3;
  std::memcpy(v2.data() + 8, &version, 4);
  write_bytes(path, v2);
  expect_rejected("model format version 3, expected 1 or 2");
  EXPECT_THAT([&] { load_forest_model(dir / "missing.fsmodel"); },
              ThrowsMessage<Error>(AllOf(HasSubstr("missing.fsmodel"), HasSubstr("no such model file"))));
}

TEST_F(FsmodelFile, AnotherClassTableIsRejected) {
  ForestModel renamed = model;
  renamed.classes[4].name = "lorry";  // the forest predicts 4: still consistent, but not LabelMeFacade's table
  save_forest_model(path, renamed);
  ForestExpectation expected{"edd", 3, Genome::thesis_best(), labelmefacade_class_table()};
  EXPECT_THAT([&] { load_forest_model(path, expected); },
              ThrowsMessage<Error>(AllOf(HasSubstr(path.string()), HasSubstr("class table"), HasSubstr("4 lorry"))));
  expected.descriptor_width = 93;
  save_forest_model(path, model);
  EXPECT_THAT([&] { load_forest_model(path, expected); },
              ThrowsMessage<Error>(AllOf(HasSubstr(path.string()), HasSubstr("expected 'edd' with 93 values"))));
}

TEST_F(FsmodelFile, AFsmodelForestIsSavedOnlyAsFsmodel) {
  const ForestModel loaded = load_forest_model(path);
  EXPECT_THAT([&] { save_forest_model(dir / "m.yml.gz", loaded); },
              ThrowsMessage<Error>(HasSubstr("only be saved as .fsmodel")));
  EXPECT_NO_THROW(require_model_file_name(dir / "x.fsmodel"));
}

TEST(ForestNodes, InconsistentNodesAreRejected) {
  using Node = RandomForest::Node;
  const Node leaf0{-1, 0.f, -1, -1, 0}, leaf1{-1, 0.f, -1, -1, 1};
  // A stump: x0 <= 0.5 -> class 3, else class 5.
  const RandomForest stump = RandomForest::from_nodes(2, {3, 5}, {{0, 0.5f, 1, 2, -1}, leaf0, leaf1}, {0});
  const cv::Mat rows = (cv::Mat_<float>(2, 2) << 0.f, 9.f, 1.f, 9.f);
  EXPECT_EQ(stump.predict(rows), (std::vector<int>{3, 5}));

  const auto rejected = [](int width, std::vector<int> classes, std::vector<Node> nodes, std::vector<int> roots,
                           const char* what) {
    EXPECT_THAT([&] { RandomForest::from_nodes(width, classes, nodes, roots); }, ThrowsMessage<Error>(HasSubstr(what)))
        << what;
  };
  rejected(2, {3, 5}, {{0, 0.5f, 0, 2, -1}, leaf0, leaf1}, {0}, "outside its tree");  // a child that is itself: a loop
  rejected(2, {3, 5}, {leaf0, {0, 0.5f, 0, 2, -1}, leaf1}, {1}, "outside its tree");  // a child before its parent
  rejected(2, {3, 5}, {{0, 0.5f, 1, 3, -1}, leaf0, leaf1}, {0}, "outside its tree");
  rejected(2, {3, 5}, {{2, 0.5f, 1, 2, -1}, leaf0, leaf1}, {0}, "outside the descriptor");
  rejected(2, {3, 5}, {{0, 0.5f, 1, 2, -1}, leaf0, {-1, 0.f, -1, -1, 2}}, {0}, "no valid class");
  rejected(2, {5, 3}, {{0, 0.5f, 1, 2, -1}, leaf0, leaf1}, {0}, "ascending");
  rejected(2, {3, 5}, {{0, 0.5f, 1, 2, -1}, leaf0, leaf1}, {3}, "root");
  rejected(2, {3, 5}, {{0, 0.5f, 1, 2, -1}, leaf0, leaf1}, {}, "no trees");
}

}  // namespace
}  // namespace facadeslam::semantics
