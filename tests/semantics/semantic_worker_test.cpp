// The semantic worker with the shipped model on a committed facade photo:
// every good point gets the forest's label and vote share at its patch
// centre; bad points and keyframes without a colour image are skipped; the
// threaded worker labels what is queued.
#include "semantics/worker/semantic_worker.hpp"

#include <cstdio>
#include <numeric>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/map/map.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam::semantics {
namespace {

class SemanticWorkerTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto photo = test::source_dir() / "data/demo/photos/images" /
                       "spatial_envelope_256x256_static_8outdoorcategories__insidecity_a140032.jpg";
    colour_ = cv::imread(photo.string(), cv::IMREAD_COLOR);
    ASSERT_FALSE(colour_.empty()) << photo;
    model_ = load_forest_model(test::source_dir() / "models/default.fsmodel");
  }

  // A keyframe of the photo (or of its grey pyramid only) with points at its
  // strongest level-0 corners.
  KeyFramePoints job(bool with_colour, std::size_t count = 40) const {
    auto pyramid = std::make_shared<const ImagePyramid>(colour_);
    auto keyframe =
        std::make_shared<const KeyFrame>(0, Frame{0, 0.0, with_colour ? colour_ : cv::Mat(), {}, pyramid}, SE3d());
    KeyFramePoints out{keyframe, {}};
    for (const Corner& c : pyramid->level(0).corners) {
      if (out.points.size() == count) break;
      out.points.push_back(
          {std::make_shared<MapPoint>(out.points.size(), PatchSource{0, pyramid, 0, {c.x, c.y}}, PointGeometry{}),
           0,
           {c.x, c.y}});
    }
    return out;
  }

  // The photo as a grey camera's frame reaches the worker: three equal channels.
  cv::Mat grey_photo() const {
    cv::Mat grey;
    cv::cvtColor(colour_, grey, cv::COLOR_BGR2GRAY);
    cv::cvtColor(grey, grey, cv::COLOR_GRAY2BGR);
    return grey;
  }
  // job() on the grey photo.
  KeyFramePoints grey_job(std::size_t count) {
    cv::Mat grey = grey_photo();
    std::swap(colour_, grey);
    KeyFramePoints out = job(true, count);
    std::swap(colour_, grey);
    return out;
  }

  cv::Mat colour_;
  ForestModel model_;
};

TEST_F(SemanticWorkerTest, LabelsEveryPointWithTheForestsVoteAtItsPatch) {
  KeyFramePointsQueue queue;
  SemanticWorker worker(model_, queue);
  const KeyFramePoints points = job(true);
  ASSERT_EQ(points.points.size(), 40u);
  worker.label(points);

  // The same descriptor and forest, by hand.
  auto descriptor = make_point_descriptor(model_.descriptor, model_.genome);
  std::vector<cv::Point2f> keypoints;
  for (const auto& [p, level, px] : points.points)
    keypoints.emplace_back(static_cast<float>(px.x()), static_cast<float>(px.y()));
  cv::Mat shares;
  const std::vector<int> expected = model_.forest.predict(descriptor->compute(colour_, keypoints), shares);
  for (std::size_t i = 0; i < points.points.size(); ++i) {
    const SemanticLabel label = points.points[i].point->label();
    EXPECT_EQ(label.label, expected[i]) << "point " << i;
    EXPECT_GT(label.confidence, 0.f);
    EXPECT_LE(label.confidence, 1.f);
  }
  const SemanticWorkerStats stats = worker.stats();
  EXPECT_EQ(stats.keyframes, 1u);
  EXPECT_EQ(stats.observations_labelled, 40u);
  EXPECT_EQ(stats.observations_skipped, 0u);
}

// With a context scale the point's votes are its patch's in the keyframe and
// in the keyframe shrunk to that scale, added: the label is their sum's arg-max.
TEST_F(SemanticWorkerTest, AddsTheVotesOfTheShrunkKeyframeWithAContextScale) {
  KeyFramePointsQueue queue;
  SemanticWorker worker(model_, queue);
  worker.use_context_scale(0.5);
  const KeyFramePoints points = job(true);
  worker.label(points);

  auto descriptor = make_point_descriptor(model_.descriptor, model_.genome);
  cv::Mat half;
  cv::resize(colour_, half, cv::Size(), 0.5, 0.5, cv::INTER_AREA);
  std::vector<cv::Point2f> keypoints, halved;
  for (const auto& [p, level, px] : points.points) {
    keypoints.emplace_back(static_cast<float>(px.x()), static_cast<float>(px.y()));
    halved.emplace_back(static_cast<float>(px.x()) * 0.5f, static_cast<float>(px.y()) * 0.5f);
  }
  cv::Mat full_shares, half_shares;
  model_.forest.predict(descriptor->compute(colour_, keypoints), full_shares);
  model_.forest.predict(descriptor->compute(half, halved), half_shares);
  const cv::Mat sum = full_shares + half_shares;
  int differs_from_full_size = 0;
  for (int i = 0; i < sum.rows; ++i) {
    cv::Point best, best_full;
    cv::minMaxLoc(sum.row(i), nullptr, nullptr, nullptr, &best);
    cv::minMaxLoc(full_shares.row(i), nullptr, nullptr, nullptr, &best_full);
    const SemanticLabel label = points.points[static_cast<std::size_t>(i)].point->label();
    EXPECT_EQ(label.label, model_.forest.classes()[static_cast<std::size_t>(best.x)]) << "point " << i;
    differs_from_full_size += best.x != best_full.x;
  }
  EXPECT_GT(differs_from_full_size, 0) << "the shrunk keyframe's votes changed no label: the test shows nothing";
  EXPECT_THROW(worker.use_context_scale(1.0), Error);
  EXPECT_THROW(worker.use_context_scale(-0.5), Error);
}

// A point measured in a second keyframe gets that view's votes added to its
// first view's: here the "second keyframe" sees each point where the first
// saw another, so the fused votes are the two rows' sum.
// Moving regions: the grid's cells go through the descriptor after the
// points, so each point's votes are what they are without the regions, and
// each point gets one region view, in a region exactly where the cells'
// calls (by hand: the same descriptor and forest) make one. The photo has
// no car, so its sky stands in for the moving class (the regions do not
// care which class moves): points under it and points away from it.
TEST_F(SemanticWorkerTest, MovingRegionsLeaveTheVotesAndGiveEachPointOneRegionView) {
  const MovingRegionOptions options{.step = 16, .sigma_cells = 3.0, .min_density = 0.1};
  const ClassSet moving = ClassSet().set(6);  // sky, see above
  KeyFramePointsQueue queue;
  SemanticWorker plain(model_, queue), with_regions(model_, queue);
  with_regions.use_moving_regions(options, moving);
  const KeyFramePoints a = job(true, 200), b = job(true, 200);
  plain.label(a);
  with_regions.label(b);

  MovingRegions regions(colour_.size(), options);
  auto descriptor = make_point_descriptor(model_.descriptor, model_.genome);
  cv::Mat shares;
  model_.forest.predict(descriptor->compute(colour_, regions.cells()), shares);
  regions.set_calls(shares, model_.forest.classes(), SemanticWorker::all_ones(), moving);

  std::size_t in_region = 0;
  for (std::size_t i = 0; i < b.points.size(); ++i) {
    const auto& [point, level, px] = b.points[i];
    EXPECT_EQ(point->votes(), a.points[i].point->votes()) << "point " << i;
    EXPECT_EQ(a.points[i].point->region_views().views, 0u);
    const bool expected = regions.contains({static_cast<float>(px.x()), static_cast<float>(px.y())});
    EXPECT_EQ(point->region_views(), (MapPoint::RegionViews{.views = 1, .in_region = expected ? 1u : 0u}))
        << "point " << i;
    EXPECT_EQ(point->in_moving_region(), expected);
    in_region += expected;
  }
  EXPECT_GT(in_region, 0u) << "the photo's sky makes no region";
  EXPECT_LT(in_region, b.points.size()) << "everything is a region";

  // No moving class, no regions (and no cells described).
  SemanticWorker no_moving(model_, queue);
  no_moving.use_moving_regions(options, ClassSet());
  const KeyFramePoints c = job(true, 20);
  no_moving.label(c);
  for (const auto& [point, level, px] : c.points) EXPECT_EQ(point->region_views().views, 0u);
}

TEST_F(SemanticWorkerTest, FusesTheVotesOfEveryKeyframeThatMeasuresAPoint) {
  KeyFramePointsQueue queue;
  SemanticWorker worker(model_, queue);
  const KeyFramePoints first = job(true, 20);
  KeyFramePoints second = first;
  for (std::size_t i = 0; i < second.points.size(); ++i) second.points[i].pixel = first.points[19 - i].pixel;
  const std::vector<ClassVotes> alone = [&] {
    std::vector<ClassVotes> votes;
    worker.label(second);
    for (const auto& [p, level, px] : second.points) votes.push_back(p->votes());
    return votes;
  }();
  for (const auto& [p, level, px] : first.points) p->set_votes({});
  worker.label(first);
  std::vector<ClassVotes> first_only;
  for (const auto& [p, level, px] : first.points) first_only.push_back(p->votes());
  worker.label(second);

  std::size_t changed = 0;
  for (std::size_t i = 0; i < first.points.size(); ++i) {
    const MapPoint& p = *first.points[i].point;
    ClassVotes sum{};
    for (std::size_t c = 0; c < sum.size(); ++c) {
      sum[c] = first_only[i][c] + alone[i][c];
      EXPECT_FLOAT_EQ(p.votes()[c], sum[c]) << "point " << i << " class " << c;
    }
    EXPECT_EQ(p.label(), label_from_votes(sum));
    EXPECT_NEAR(std::accumulate(sum.begin(), sum.end(), 0.f), 2.f, 1e-4) << "two views, one vote each";
    changed += label_from_votes(first_only[i]).label != p.label().label;
  }
  EXPECT_EQ(worker.stats().observations_labelled, 60u);
  std::printf("fusion changed %zu of %zu labels\n", changed, first.points.size());
}

TEST_F(SemanticWorkerTest, SkipsBadPointsAndKeyframesWithoutColour) {
  KeyFramePointsQueue queue;
  SemanticWorker worker(model_, queue);
  const KeyFramePoints grey = job(false, 10);
  worker.label(grey);
  for (const auto& [p, level, px] : grey.points) EXPECT_EQ(p->label().label, kUnlabelled);

  Map map;
  const KeyFramePoints coloured = job(true, 10);
  std::vector<std::shared_ptr<MapPoint>> points;
  for (const auto& [p, level, px] : coloured.points) points.push_back(p);
  map.add({}, points);
  map.update([&](MapEditor& edit) { edit.mark_bad(*points[3]); });
  worker.label(coloured);
  EXPECT_EQ(points[3]->label().label, kUnlabelled);
  EXPECT_NE(points[4]->label().label, kUnlabelled);
  EXPECT_EQ(worker.stats().observations_skipped, 11u);
  EXPECT_EQ(worker.stats().observations_labelled, 9u);
}

// A grey sequence decoded to BGR (KITTI): three equal channels. The colour
// forest learnt from colour photographs; its labels on grey would be wrong,
// so without a grey model, none.
TEST_F(SemanticWorkerTest, LeavesTheKeyframesOfAGreySequenceUnlabelledWithoutAGreyModel) {
  EXPECT_TRUE(is_grey(grey_photo()));
  EXPECT_FALSE(is_grey(colour_));
  const KeyFramePoints job_of_grey = grey_job(10);
  KeyFramePointsQueue queue;
  SemanticWorker worker(model_, queue);
  worker.label(job_of_grey);
  for (const auto& [p, level, px] : job_of_grey.points) EXPECT_EQ(p->label().label, kUnlabelled);
  EXPECT_EQ(worker.stats().grey_keyframes, 1u);
  EXPECT_EQ(worker.stats().observations_labelled, 0u);
  EXPECT_FALSE(worker.stats().grey_model);
}

// With the shipped grey model (models/grey.fsmodel), grey keyframes are
// labelled by it, with its own descriptor, and colour ones by the colour model.
TEST_F(SemanticWorkerTest, LabelsGreyKeyframesWithTheGreyModel) {
  const ForestModel grey_model = load_forest_model(test::source_dir() / "models/grey.fsmodel");
  const cv::Mat grey = grey_photo();
  const KeyFramePoints colour_job = job(true, 20);
  const KeyFramePoints grey_points = grey_job(20);
  KeyFramePointsQueue queue;
  SemanticWorker worker(model_, queue);
  worker.use_grey_model(grey_model);
  worker.label(grey_points);
  worker.label(colour_job);

  const auto expected_labels = [](const ForestModel& model, const cv::Mat& image, const KeyFramePoints& points) {
    auto descriptor = make_point_descriptor(model.descriptor, model.genome);
    std::vector<cv::Point2f> keypoints;
    for (const auto& [p, level, px] : points.points)
      keypoints.emplace_back(static_cast<float>(px.x()), static_cast<float>(px.y()));
    cv::Mat shares;
    return model.forest.predict(descriptor->compute(image, keypoints), shares);
  };
  // The class prior is all ones here, so the label is the forest's vote.
  const std::vector<int> from_grey = expected_labels(grey_model, grey, grey_points);
  const std::vector<int> from_colour = expected_labels(model_, colour_, colour_job);
  for (std::size_t i = 0; i < grey_points.points.size(); ++i) {
    EXPECT_EQ(grey_points.points[i].point->label().label, from_grey[i]) << "grey point " << i;
    EXPECT_EQ(colour_job.points[i].point->label().label, from_colour[i]) << "colour point " << i;
  }
  const SemanticWorkerStats stats = worker.stats();
  EXPECT_TRUE(stats.grey_model);
  EXPECT_EQ(stats.grey_keyframes, 1u);
  EXPECT_EQ(stats.observations_labelled, 40u);
  // The two models are different descriptors: the thesis genome on grey, the GA's on colour.
  EXPECT_NE(grey_model.genome.to_string(), model_.genome.to_string());
}

TEST_F(SemanticWorkerTest, TheThreadLabelsWhatIsQueuedBeforeItStops) {
  KeyFramePointsQueue queue;
  SemanticWorker worker(model_, queue);
  worker.start();
  std::vector<KeyFramePoints> jobs;
  for (int k = 0; k < 3; ++k) {
    jobs.push_back(job(true, 15));
    queue.push(jobs.back());
  }
  worker.stop();
  for (const auto& j : jobs)
    for (const auto& [p, level, px] : j.points) EXPECT_NE(p->label().label, kUnlabelled);
  EXPECT_EQ(worker.stats().keyframes, 3u);
}

TEST(SemanticWorker, RejectsAModelWhoseForestDoesNotFitItsDescriptor) {
  ForestModel model = load_forest_model(test::source_dir() / "models/default.fsmodel");
  // One value fewer than the forest was trained on.
  DescriptorParams params = model.genome.decode();
  for (std::size_t i = 0; i < params.activation.size(); ++i)
    if (params.activation[i]) {
      params.activation.reset(i);
      break;
    }
  model.genome = Genome::encode(params);
  KeyFramePointsQueue queue;
  EXPECT_THROW(SemanticWorker(model, queue), Error);
}

}  // namespace
}  // namespace facadeslam::semantics
