// Frames from real clocks: rows a fraction of a millisecond apart share a frame, implausible units
// are refused with the unit they look like, gaps are filled at the log's rate, and a stream gives
// the frames a whole-file read gives, each as soon as the next frame's first row is in.

#include "io/parse_log.h"
#include "opf/io/input_error.h"
#include "opf/io/measurement_log.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace opf {
namespace {

/// The default options with `set` applied.
template <class Set>
LogReadOptions with(Set set) {
  LogReadOptions options;
  set(options);
  return options;
}

constexpr const char* kHeader = "t,object,x,y,z,qx,qy,qz,qw\n";

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

std::string row(double t, const std::string& object, double x, double y = 0.0, double z = 0.0) {
  std::ostringstream s;
  s.precision(17);
  s << t << ',' << object << ',' << x << ',' << y << ',' << z << ",0,0,0,1\n";
  return s.str();
}

// Three objects at 30 Hz, each stamped by its own clock: offsets of 0, 0.3 and 0.45 ms plus a
// per-row jitter of up to 0.05 ms, written in the order the sensors report (not sorted).
std::string jittered_log(int frames, double time_scale = 1.0, double length_scale = 1.0) {
  const std::vector<std::string> objects = {"ball", "mug", "box"};
  const double offsets[] = {0.0, 0.0003, 0.00045};
  std::string text = kHeader;
  for (int k = 0; k < frames; ++k)
    for (int i = 2; i >= 0; --i) {
      const double jitter = 0.00005 * std::sin(7.0 * k + i);
      const double t = k / 30.0 + offsets[i] + jitter;
      text += row(t * time_scale, objects[static_cast<std::size_t>(i)],
                  (0.1 * i + 0.3 * t) * length_scale);
    }
  return text;
}

TEST(FrameAssembly, JitteredClocksGiveOneFramePerRealFrame) {
  const MeasurementLog log = parse(jittered_log(60));
  ASSERT_EQ(log.frames.size(), 60u);
  for (std::size_t k = 0; k < log.frames.size(); ++k) {
    EXPECT_EQ(log.frames[k].detections.size(), 3u) << k;
    // At the mean of its rows' times: within the clocks' spread of the real frame time.
    EXPECT_NEAR(log.frames[k].t, static_cast<double>(k) / 30.0 + 0.00025, 0.0001) << k;
    EXPECT_FALSE(log.frames[k].filled);
  }
  EXPECT_NEAR(log.report.frame_tolerance, 0.25 / 30.0, 1e-4);
  // A tolerance of 0 groups equal times only: every row its own frame (gaps not filled, or the
  // 0.3 ms between them would set the frame period).
  const MeasurementLog exact = parse(jittered_log(60), with([](LogReadOptions& o) {
                                       o.frame_tolerance = 0.0;
                                       o.fill_gaps = false;
                                     }));
  EXPECT_EQ(exact.frames.size(), 180u);
}

// A detector that sees the objects now and then: every 2 s in two consecutive frames of 30 Hz,
// and once more 1 s later. Two of one object's three intervals are gaps; the tolerance comes from
// the frame period all the same (the median interval, a gap, made it 0.24 s, and each pair's two
// rows were refused as one frame).
TEST(FrameAssembly, ADetectorSeeingObjectsNowAndThenGivesItsFramePeriod) {
  std::string text = kHeader;
  for (int block = 0; block < 6; ++block)
    for (const double offset : {0.0, 1.0 / 30.0, 1.0}) {
      const double t = 2.0 * block + offset;
      text += row(t, "ball", 0.1 * t) + row(t + 0.0003, "mug", 1.0);
    }
  const MeasurementLog log = parse(text, with([](LogReadOptions& o) { o.fill_gaps = false; }));
  EXPECT_NEAR(log.report.frame_tolerance, 0.25 / 30.0, 1e-9);
  ASSERT_EQ(log.frames.size(), 18u);
  for (const Frame& frame : log.frames) EXPECT_EQ(frame.detections.size(), 2u) << frame.t;
}

TEST(FrameAssembly, EqualTimesKeepTheirExactTimeAndRowOrder) {
  const MeasurementLog log = parse(std::string(kHeader) + row(0.1, "mug", 4) + row(0.1, "ball", 1) +
                                   row(0.2, "ball", 1) + row(0.2, "mug", 4));
  ASSERT_EQ(log.frames.size(), 2u);
  EXPECT_EQ(log.frames[0].t, 0.1);  // not a mean that rounds
  EXPECT_EQ(log.frames[1].t, 0.2);
  EXPECT_EQ(log.frames[0].detections[0].object, "mug");
}

TEST(FrameAssembly, TwoRowsOfOneObjectWithinTheToleranceAreRefused) {
  const InputError e = parse_error(
      std::string(kHeader) + row(0.0, "ball", 0) + row(0.001, "ball", 0) + row(0.1, "ball", 0),
      with([](LogReadOptions& o) { o.frame_tolerance = 0.01; }));
  EXPECT_EQ(e.line(), 3u);
  EXPECT_EQ(e.field(), "t");
  EXPECT_TRUE(contains(e.message(), "line 2")) << e.what();
  EXPECT_TRUE(contains(e.message(), "--frame-tolerance")) << e.what();
}

TEST(FrameAssembly, TimesInOtherUnitsAreRefusedWithTheUnitTheyLookLike) {
  const struct {
    double scale;
    const char* unit;
  } cases[] = {{1e3, "ms"}, {1e6, "us"}, {1e9, "ns"}};
  for (const auto& c : cases) {
    const InputError e = parse_error(jittered_log(10, c.scale));
    EXPECT_EQ(e.file(), "log.csv");
    EXPECT_GT(e.line(), 1u);
    EXPECT_EQ(e.field(), "t");
    EXPECT_TRUE(contains(e.message(), std::string("--time-unit ") + c.unit)) << e.what();
  }
  // Given the unit, the same frames as the log in seconds.
  const MeasurementLog seconds = parse(jittered_log(10));
  const MeasurementLog ms =
      parse(jittered_log(10, 1e3),
            with([](LogReadOptions& o) { o.time_unit = TimeUnit::kMilliseconds; }));
  ASSERT_EQ(ms.frames.size(), seconds.frames.size());
  for (std::size_t k = 0; k < ms.frames.size(); ++k)
    EXPECT_NEAR(ms.frames[k].t, seconds.frames[k].t, 1e-12);
}

TEST(FrameAssembly, EpochTimesInMillisecondsAreRefusedEvenInAOneFrameLog) {
  const InputError e = parse_error(std::string(kHeader) + row(1.7e12, "ball", 0));
  EXPECT_EQ(e.line(), 2u);
  EXPECT_TRUE(contains(e.message(), "--time-unit ms")) << e.what();
  // Epoch seconds are fine.
  EXPECT_EQ(parse(std::string(kHeader) + row(1.7e9, "ball", 0)).frames.size(), 1u);
}

TEST(FrameAssembly, PositionsInMillimetresAreRefusedUnlessSaid) {
  const InputError e = parse_error(jittered_log(10, 1.0, 1000.0));
  EXPECT_EQ(e.field(), "x,y,z");
  EXPECT_TRUE(contains(e.message(), "--length-unit mm")) << e.what();
  const MeasurementLog mm =
      parse(jittered_log(10, 1.0, 1000.0),
            with([](LogReadOptions& o) { o.length_unit = LengthUnit::kMillimetres; }));
  const MeasurementLog m = parse(jittered_log(10));
  EXPECT_NEAR(mm.frames[5].find("box")->pose.x(), m.frames[5].find("box")->pose.x(), 1e-12);
  // A static object logged in metres with millimetre noise is not taken for millimetres.
  std::string still = kHeader;
  for (int k = 0; k < 20; ++k) still += row(k / 100.0, "cup", 0.5 + 0.001 * std::sin(k));
  EXPECT_EQ(parse(still).frames.size(), 20u);
}

TEST(FrameAssembly, FramesUnderANanosecondApartAreRefused) {
  // A log at 30 Hz with its times divided by 1e12 (picoseconds read as seconds, say): the speed
  // check is told the unit is right, so the frames 33 ps apart are what is left to refuse.
  const LogReadOptions metres =
      with([](LogReadOptions& o) { o.length_unit = LengthUnit::kMetres; });
  const InputError e = parse_error(jittered_log(10, 1e-12), metres);
  EXPECT_EQ(e.file(), "log.csv");
  EXPECT_GT(e.line(), 1u);
  EXPECT_EQ(e.field(), "t");
  EXPECT_TRUE(contains(e.message(), "under 1 ns apart")) << e.what();
  // Frames 1 ns apart are the finest clock taken.
  std::string fine = kHeader;
  for (int k = 0; k < 20; ++k) fine += row(1e-9 * k, "ball", 0.0);
  EXPECT_EQ(parse(fine, metres).frames.size(), 20u);
}

TEST(FrameAssembly, FramesMissingInsideAGapAreFilledAtTheLogsRate) {
  std::string text = kHeader;
  for (int k = 0; k < 200; ++k)
    if (k < 100 || k >= 150) text += row(k / 100.0, "ball", 0.01 * k);  // no rows for 0.5 s
  const MeasurementLog log = parse(text);
  ASSERT_EQ(log.frames.size(), 200u);
  for (int k = 0; k < 200; ++k) {
    EXPECT_NEAR(log.frames[static_cast<std::size_t>(k)].t, k / 100.0, 1e-9) << k;
    EXPECT_EQ(log.frames[static_cast<std::size_t>(k)].filled, k >= 100 && k < 150) << k;
  }
  EXPECT_EQ(log.report.filled_frames, 50u);
  EXPECT_EQ(log.report.gaps, 1u);
  EXPECT_NEAR(log.report.frame_period, 0.01, 1e-9);
  // --no-fill keeps the log's frames; --rate sets the rate.
  EXPECT_EQ(parse(text, with([](LogReadOptions& o) { o.fill_gaps = false; })).frames.size(), 150u);
  EXPECT_EQ(parse(text, with([](LogReadOptions& o) { o.rate = 25.0; })).frames.size(),
            162u);  // 12 frames of 0.04 s in 0.51 s
}

TEST(FrameAssembly, AClockJumpIsNotFilled) {
  std::string text = kHeader;
  for (int k = 0; k < 10; ++k) text += row(k / 100.0, "ball", 0);
  for (int k = 0; k < 10; ++k) text += row(60.0 + k / 100.0, "ball", 0);
  const MeasurementLog log = parse(text);
  EXPECT_EQ(log.frames.size(), 20u);
  EXPECT_EQ(log.report.long_gaps, 1u);
}

TEST(FrameAssembly, MappedColumnNamesAreRead) {
  const std::string text =
      "time,name,px,py,pz,rx,ry,rz,rw\n"
      "0,ball,1,2,3,0,0,0,1\n"
      "0.1,ball,1,2,3,0,0,1,0\n";
  const MeasurementLog log = parse(text, with([](LogReadOptions& o) {
                                     o.columns = parse_column_mapping(
                                         "t=time,object=name,x=px,y=py,z=pz,qx=rx,qy=ry,"
                                         "qz=rz,qw=rw");
                                   }));
  ASSERT_EQ(log.frames.size(), 2u);
  EXPECT_EQ(log.frames[1].find("ball")->pose.z(), 3.0);
  EXPECT_NEAR(std::abs(log.frames[1].find("ball")->pose.yaw()), M_PI, 1e-9);
  // A mapped column the header lacks is named by the file's name.
  const InputError e =
      parse_error(text, with([](LogReadOptions& o) { o.columns = parse_column_mapping("qx=qa"); }));
  EXPECT_TRUE(contains(e.message(), "qa")) << e.what();
  EXPECT_THROW(parse_column_mapping("qx"), std::invalid_argument);
  EXPECT_THROW(parse_column_mapping("speed=v"), std::invalid_argument);
  EXPECT_THROW(parse_column_mapping("qx=a,qy=a"), std::invalid_argument);
}

std::vector<Frame> stream_frames(const std::string& text) {
  std::istringstream in(text);
  MeasurementStream stream(in, "log.csv");
  std::vector<Frame> frames;
  while (auto frame = stream.next()) frames.push_back(std::move(*frame));
  return frames;
}

TEST(FrameAssembly, AStreamGivesTheFramesOfTheWholeFile) {
  std::string text = kHeader;
  // Jittered clocks, written in time order, with a gap.
  std::string sorted = jittered_log(40);
  std::vector<std::pair<double, std::string>> rows;
  std::istringstream lines(sorted.substr(sorted.find('\n') + 1));
  for (std::string line; std::getline(lines, line);)
    if (line.rfind("0.6", 0) != 0) rows.emplace_back(std::stod(line), line + "\n");
  std::sort(rows.begin(), rows.end());
  for (const auto& [t, line] : rows) text += line;
  const std::vector<Frame> streamed = stream_frames(text);
  const MeasurementLog whole = parse(text);
  ASSERT_EQ(streamed.size(), whole.frames.size());
  for (std::size_t k = 0; k < streamed.size(); ++k) {
    EXPECT_EQ(streamed[k].t, whole.frames[k].t);
    EXPECT_EQ(streamed[k].filled, whole.frames[k].filled);
    ASSERT_EQ(streamed[k].detections.size(), whole.frames[k].detections.size());
    for (std::size_t i = 0; i < streamed[k].detections.size(); ++i)
      EXPECT_EQ(streamed[k].detections[i].object, whole.frames[k].detections[i].object);
  }
  EXPECT_GT(whole.report.filled_frames, 0u);
}

TEST(FrameAssembly, AStreamAnswersEachFrameWhenTheNextOneStarts) {
  std::string text = kHeader;
  std::vector<std::size_t> frame_end;  // offset just past each frame's last row
  for (int k = 0; k < 30; ++k) {
    text += row(k / 30.0, "ball", 0.01 * k);
    text += row(k / 30.0 + 0.0003, "mug", 0.5);
    frame_end.push_back(text.size());
  }
  std::istringstream in(text);
  MeasurementStream stream(in, "log.csv");
  for (int k = 0; k < 30; ++k) {
    ASSERT_TRUE(stream.next()) << k;
    // Past the first rows (read to infer the units), frame k is out once the first row of
    // frame k + 1 is read, and nothing further.
    if (k >= 10 && k + 1 < 30) {
      const auto consumed = static_cast<std::size_t>(in.tellg());
      const std::size_t next_row = row((k + 1) / 30.0, "ball", 0.01 * (k + 1)).size();
      EXPECT_LE(consumed, frame_end[static_cast<std::size_t>(k)] + next_row) << k;
    }
  }
  EXPECT_FALSE(stream.next());
}

TEST(FrameAssembly, AStreamRefusesARowFromAFrameAlreadyOut) {
  std::string text = kHeader;
  for (int k = 0; k < 20; ++k) text += row(k / 30.0, "ball", 0);
  text += row(0.1, "mug", 0);  // line 22: frame 3 is long out
  std::istringstream in(text);
  MeasurementStream stream(in, "<stdin>");
  try {
    while (stream.next()) {
    }
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "<stdin>");
    EXPECT_EQ(e.line(), 22u);
    EXPECT_TRUE(contains(e.message(), "out of order")) << e.what();
  }
  // A whole file may be unsorted: the row joins frame 3.
  const MeasurementLog whole = parse(text);
  ASSERT_EQ(whole.frames.size(), 20u);
  EXPECT_NE(whole.frames[3].find("mug"), nullptr);
}

TEST(FrameAssembly, AStreamWithoutDetectionsIsRefusedAtItsEnd) {
  std::istringstream in(std::string(kHeader) + "0,ball,,,,,,,\n");
  MeasurementStream stream(in, "<stdin>");
  EXPECT_THROW(stream.next(), InputError);
}

}  // namespace
}  // namespace opf
