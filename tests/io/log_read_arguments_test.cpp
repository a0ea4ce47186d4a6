// The log options checked once for the program and the Python module, each refusal in the
// caller's names, and what a file's format implies.

#include "opf/io/log_read_arguments.h"
#include "io/scratch_directory.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

namespace opf {
namespace {

namespace fs = std::filesystem;

std::string program_name(std::string_view option) {
  return option == "fill" ? "--no-fill" : "--" + std::string(option);
}
std::string python_name(std::string_view option) {
  return option == "fill" ? "fill=False" : std::string(option);
}

std::string refusal(const LogArguments& given, const OptionNamer& name, const std::string& path) {
  try {
    log_read_options(given, path, name);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "accepted";
}

TEST(LogReadArguments, RefusalsNameTheOptionAsTheCallerDoes) {
  LogArguments bad_unit;
  bad_unit.time_unit = "h";
  EXPECT_EQ(refusal(bad_unit, program_name, "log.csv"),
            "option '--time_unit': expected s, ms, us or ns, got \"h\"");
  EXPECT_EQ(refusal(bad_unit, python_name, "log.csv"),
            "option 'time_unit': expected s, ms, us or ns, got \"h\"");
  LogArguments both;
  both.rate = 30.0;
  both.fill = false;
  EXPECT_EQ(refusal(both, python_name, "log.csv"),
            "options 'rate' and 'fill=False' contradict each other: rate sets the rate gaps are "
            "filled at");
  LogArguments negative;
  negative.frame_tolerance = -0.1;
  EXPECT_EQ(refusal(negative, program_name, "log.csv"),
            "option '--frame_tolerance' expects seconds >= 0");
}

TEST(LogReadArguments, ATumFileIsOneObjectNamedAfterIt) {
  LogArguments tum;
  tum.format = "tum";
  const LogReadOptions options = log_read_options(tum, "runs/groundtruth.txt", python_name);
  EXPECT_EQ(options.format, LogFormat::kTum);
  EXPECT_EQ(options.object, "groundtruth");
  tum.columns = "qx=rx";
  EXPECT_EQ(
      refusal(tum, python_name, "g.txt"),
      "option 'columns' renames CSV columns; a TUM, MOTChallenge, ASL or KITTI file's columns "
      "are its format's");
  tum.columns.reset();
  EXPECT_NE(refusal(tum, program_name, "-").find("needs its object's name: --object NAME"),
            std::string::npos);
}

TEST(LogReadArguments, AnAslFileIsOneObjectNamedAfterItTimedInNanoseconds) {
  LogArguments asl;
  asl.format = "euroc";
  const LogReadOptions options = log_read_options(asl, "mocap0/vicon.csv", program_name);
  EXPECT_EQ(options.format, LogFormat::kEuroc);
  EXPECT_EQ(options.object, "vicon");
  EXPECT_EQ(stated_time_unit(options), TimeUnit::kNanoseconds);
  EXPECT_NE(refusal(asl, program_name, "-")
                .find("an ASL log on standard input needs its "
                      "object's name: --object NAME"),
            std::string::npos);
  asl.format = "kml";
  EXPECT_EQ(refusal(asl, program_name, "a.csv"),
            "option '--format': expected csv, tum, mot, euroc or kitti, got \"kml\"");
}

TEST(LogReadArguments, AMotChallengeFileTakesItsSequencesFrameRate) {
  const fs::path sequence = scratch_directory("opf_log_read_arguments") / "MOT17-02";
  fs::create_directories(sequence / "gt");
  std::ofstream(sequence / "seqinfo.ini") << "[Sequence]\r\nframeRate=14\r\n";
  LogArguments boxes;
  boxes.format = "mot";
  boxes.fill = false;  // the rate times the frames: not a contradiction here
  const LogReadOptions options =
      log_read_options(boxes, (sequence / "gt" / "gt.txt").string(), program_name);
  EXPECT_EQ(options.rate, 14.0);
  boxes.time_unit = "ms";
  EXPECT_EQ(refusal(boxes, program_name, (sequence / "gt" / "gt.txt").string()),
            "option '--time_unit' does not apply to a MOTChallenge file (ids, pixels, frame "
            "numbers)");
  fs::remove_all(sequence.parent_path());
  boxes.time_unit.reset();
  EXPECT_NE(refusal(boxes, program_name, "gt.txt").find("need the frame rate: --rate HZ"),
            std::string::npos);
}

}  // namespace
}  // namespace opf
