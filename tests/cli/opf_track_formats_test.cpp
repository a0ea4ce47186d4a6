// The formats people have, end to end: a TUM trajectory and an ASL CSV track with no option, and
// the estimates are written as TUM (one file per object) that read back; a log that would be read
// wrong (a column read as two fields, quaternions written w first) is refused or warned about.

#include "cli/opf_program.h"
#include "opf/io/estimate_csv.h"
#include "opf/io/log_row_reader.h"
#include "opf/io/measurement_log.h"

#include "opf/core/pose_conversion.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

namespace opf {
namespace {

namespace fs = std::filesystem;

const std::string kExampleLog = std::string(OPF_SOURCE_DIR) + "/experiments/data/example_log.csv";

// A SLAM-style trajectory: epoch times, 30 Hz, a turn about z, lines 20-29 missing (a gap).
void write_tum_trajectory(const fs::path& path) {
  std::ofstream out(path);
  out << "# ground truth trajectory\n# timestamp tx ty tz qx qy qz qw\n";
  out.precision(17);
  for (int k = 0; k < 60; ++k) {
    if (k >= 20 && k < 30) continue;
    const double t = 1403715273.0 + k / 30.0, yaw = 0.01 * k;
    out << t << ' ' << 0.2 * k / 30.0 << " 0.1 1.5 0 0 " << std::sin(yaw / 2) << ' '
        << std::cos(yaw / 2) << '\n';
  }
}

LogReadOptions tum(const std::string& object) {
  LogReadOptions options;
  options.format = LogFormat::kTum;
  options.object = object;
  options.fill_gaps = false;
  return options;
}

TEST_F(OpfProgram, ATumTrajectoryTracksWithNoOptionAndItsEstimatesReadBackAsTum) {
  const fs::path log = dir_ / "room1.txt";
  write_tum_trajectory(log);
  const std::string common = " --estimator cvkf --seed 2 --quiet";
  ASSERT_EQ(run("track --in " + log.string() + " --out " + (dir_ / "est.csv").string() + common), 0)
      << err();
  ASSERT_EQ(run("track --in " + log.string() + " --out " + (dir_ / "est.tum").string() + common), 0)
      << err();
  // The CSV names the object after the file; the TUM file holds the same main estimates.
  const std::vector<EstimateRecord> rows = read_estimate_csv(dir_ / "est.csv");
  ASSERT_EQ(rows.size(), 60u);  // 50 frames of the log and 10 filled in its gap
  EXPECT_EQ(rows.front().object, "room1");
  const MeasurementLog back = read_measurement_log(dir_ / "est.tum", tum("est"));
  ASSERT_EQ(back.frames.size(), rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const mrpt::poses::CPose3D& read = back.frames[i].detections.at(0).pose;
    EXPECT_DOUBLE_EQ(back.frames[i].t, rows[i].t);
    EXPECT_LT((translation_of(read) - translation_of(rows[i].pose)).norm(), 1e-12) << i;
    EXPECT_LT(orientation_of(read).angularDistance(orientation_of(rows[i].pose)), 1e-9) << i;
  }
  // --format tum reads it (its name says nothing), --object names the object.
  const fs::path renamed = dir_ / "est.data";
  fs::copy_file(dir_ / "est.tum", renamed);
  ASSERT_EQ(run("track --in " + renamed.string() + " --format tum --object cup --out " +
                (dir_ / "again.csv").string() + common),
            0)
      << err();
  EXPECT_EQ(read_estimate_csv(dir_ / "again.csv").front().object, "cup");
}

// The same trajectory as an ASL CSV (EuRoC's and TUM VI's ground truth: nanoseconds, the
// quaternion w first, further columns) tracks with no option to the TUM file's estimates, and an
// ASL truth scores it as a TUM truth would.
TEST_F(OpfProgram, AnAslCsvTracksWithNoOptionAsItsTumTwin) {
  const fs::path tum_log = dir_ / "room1.txt", asl_log = dir_ / "room1.csv";
  write_tum_trajectory(tum_log);
  const MeasurementLog poses = read_measurement_log(tum_log, tum("room1"));
  {
    std::ofstream out(asl_log);
    out << "#timestamp [ns],p_RS_R_x [m],p_RS_R_y [m],p_RS_R_z [m],q_RS_w [],q_RS_x [],q_RS_y [],"
           "q_RS_z [],v_RS_R_x [m s^-1]\n";
    out.precision(17);
    for (const Frame& frame : poses.frames) {
      const Detection& d = frame.detections.at(0);
      const Eigen::Vector3d p = translation_of(d.pose);
      const Eigen::Quaterniond q = orientation_of(d.pose);
      out << static_cast<long long>(std::llround(frame.t * 1e9)) << ',' << p.x() << ',' << p.y()
          << ',' << p.z() << ',' << q.w() << ',' << q.x() << ',' << q.y() << ',' << q.z()
          << ",0.2\n";
    }
  }
  const std::string common = " --estimator cvkf --seed 2 --quiet";
  for (const fs::path& log : {tum_log, asl_log})
    ASSERT_EQ(run("track --in " + log.string() + " --out " + (dir_ / log.extension()).string() +
                  ".est.csv" + common),
              0)
        << err();
  const std::vector<EstimateRecord> from_tum = read_estimate_csv(dir_ / ".txt.est.csv");
  const std::vector<EstimateRecord> from_asl = read_estimate_csv(dir_ / ".csv.est.csv");
  ASSERT_EQ(from_asl.size(), from_tum.size());
  ASSERT_EQ(from_asl.size(), 60u);
  EXPECT_EQ(from_asl.front().object, "room1");
  for (std::size_t i = 0; i < from_asl.size(); ++i) {
    // Epoch times differ by their rounding (a double's step at 1.4e9 s is 0.24 us), so the
    // filters' intervals, and at 0.2 m/s the estimates by about 1e-8 m: within a micrometre.
    EXPECT_NEAR(from_asl[i].t, from_tum[i].t, 1e-6) << i;
    EXPECT_LT((translation_of(from_asl[i].pose) - translation_of(from_tum[i].pose)).norm(), 1e-6)
        << i;
    EXPECT_LT(orientation_of(from_asl[i].pose).angularDistance(orientation_of(from_tum[i].pose)),
              1e-6)
        << i;
    EXPECT_EQ(from_asl[i].mode, from_tum[i].mode) << i;
  }
  // The truth of the log's one object, whatever its file is called.
  fs::copy_file(asl_log, dir_ / "vicon0.csv");
  ASSERT_EQ(run("evaluate --in " + asl_log.string() + " --truth " + (dir_ / "vicon0.csv").string() +
                " --estimators cvkf --seeds 1 --out " + (dir_ / "scores.csv").string()),
            0)
      << err();
  EXPECT_NE(read(dir_ / "scores.csv").find("cvkf"), std::string::npos);
}

// A copy of the CSV log `from` at `to` with each row's t,object,x,y,z alone.
void write_positions_only(const std::string& from, const fs::path& to) {
  std::ifstream in(from);
  std::ofstream out(to);
  for (std::string line; std::getline(in, line);) {
    std::size_t end = 0;
    for (int field = 0; field < 5; ++field) end = line.find(',', end) + 1;
    out << line.substr(0, end - 1) << "\n";
  }
}

// A detector of positions alone: its log tracks at the identity orientation, each position as
// from the whole pose (cvkf's translation filter never reads the orientation), with a note that
// the orientations say nothing; from a stream the same, and of a truth of positions in evaluate.
TEST_F(OpfProgram, ALogOfPositionsAloneTracksAtTheIdentityOrientationWithANote) {
  const fs::path positions = dir_ / "positions.csv", truth = dir_ / "truth_positions.csv";
  write_positions_only(kExampleLog, positions);
  write_positions_only(std::string(OPF_SOURCE_DIR) + "/experiments/data/example_truth.csv", truth);
  const std::string note = ": note: " + positions.string() + ": " + positions_only_note() + "\n";
  const std::string full = (dir_ / "full.csv").string(), est = (dir_ / "est.csv").string();
  const std::string track = "track --estimator cvkf --in ";
  ASSERT_EQ(run(track + kExampleLog + " --out " + full), 0) << err();
  ASSERT_EQ(run(track + positions.string() + " --out " + est), 0) << err();
  EXPECT_EQ(err(), "opf track" + note);
  const std::vector<EstimateRecord> a = read_estimate_csv(full), b = read_estimate_csv(est);
  ASSERT_EQ(b.size(), 360u);  // 2 objects, 180 frames
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(translation_of(b[i].pose), translation_of(a[i].pose)) << "row " << i;
    EXPECT_EQ(orientation_of(b[i].pose).coeffs(), Eigen::Quaterniond::Identity().coeffs())
        << "row " << i;
  }
  ASSERT_EQ(run(track + positions.string() + " --stream --out " + est), 0) << err();
  EXPECT_EQ(err(), "opf track" + note);
  ASSERT_EQ(run(track + positions.string() + " --quiet --out " + est), 0) << err();
  EXPECT_EQ(err(), "");
  const std::string evaluate = "evaluate --estimators cvkf --seeds 1 --in ";
  ASSERT_EQ(run(evaluate + kExampleLog + " --truth " + truth.string()), 0) << err();
  EXPECT_EQ(err(), "opf evaluate: note: " + truth.string() + ": " + positions_only_note() + "\n");
  ASSERT_EQ(run(evaluate + positions.string() + " --truth " + truth.string()), 0) << err();
  EXPECT_EQ(err(), "opf evaluate" + note);  // the log's note says it of both
}

TEST_F(OpfProgram, TumOutputIsOneFilePerObjectAndNeedsTheWholeLog) {
  const std::string out = (dir_ / "est.tum").string();
  ASSERT_EQ(run("track --in " + kExampleLog + " --out " + out + " --estimator cvkf --quiet"), 0)
      << err();
  EXPECT_FALSE(fs::exists(out));
  EXPECT_EQ(read_measurement_log(dir_ / "est_ball.tum", tum("ball")).objects.size(), 1u);
  EXPECT_EQ(read_measurement_log(dir_ / "est_mug.tum", tum("mug")).objects.size(), 1u);
  EXPECT_EQ(run("track --in " + kExampleLog + " --out - --out-format tum"), 2);
  EXPECT_NE(err().find("standard output holds one, and the log has 2"), std::string::npos) << err();
  EXPECT_EQ(run("track --in " + kExampleLog + " --stream --out " + out), 2);
  EXPECT_NE(err().find("not from a stream"), std::string::npos) << err();
  EXPECT_EQ(run("track --in " + kExampleLog + " --out x.csv --out-format kml"), 2);
}

TEST_F(OpfProgram, EvaluateComparesATumLogWithATumTruthOfAnotherName) {
  write_tum_trajectory(dir_ / "slam_output.txt");
  write_tum_trajectory(dir_ / "groundtruth.txt");
  ASSERT_EQ(run("evaluate --in " + (dir_ / "slam_output.txt").string() + " --truth " +
                (dir_ / "groundtruth.txt").string() + " --estimators cvkf --seeds 1"),
            0)
      << err();
  EXPECT_NE(out().find("1 objects"), std::string::npos) << out();
}

TEST_F(OpfProgram, AMotChallengeFileTracksItsIdsAtItsSequencesFrameRate) {
  // The MOTChallenge layout: MOT17-02/seqinfo.ini beside MOT17-02/gt/gt.txt.
  fs::create_directories(dir_ / "MOT17-02" / "gt");
  std::ofstream(dir_ / "MOT17-02" / "seqinfo.ini") << "[Sequence]\nname=MOT17-02\nframeRate=30\n";
  {
    std::ofstream gt(dir_ / "MOT17-02" / "gt" / "gt.txt");
    for (int frame = 1; frame <= 40; ++frame)
      if (frame < 15 || frame > 25) gt << frame << ",7," << 100 + 2 * frame << ",200,40,80,1,1,1\n";
  }
  const std::string gt = (dir_ / "MOT17-02" / "gt" / "gt.txt").string();
  const std::string est = (dir_ / "est.csv").string();
  ASSERT_EQ(run("track --in " + gt + " --out " + est + " --estimator cvkf --quiet"), 0) << err();
  const std::vector<EstimateRecord> rows = read_estimate_csv(est);
  ASSERT_EQ(rows.size(), 40u);  // 29 boxes and the 11 frames of the gap, filled
  EXPECT_EQ(rows.front().object, "7");
  EXPECT_NEAR(rows.back().t, 39.0 / 30.0, 1e-9);
  // Boxes moving 2 px per frame at constant velocity: through the gap within a millimetre.
  EXPECT_NEAR(rows[20].pose.x(), (100 + 2 * 21 + 20) * 1e-3, 1e-3);
  // Without a seqinfo.ini the frame rate must be given; ids name the objects, not --object.
  fs::remove(dir_ / "MOT17-02" / "seqinfo.ini");
  EXPECT_EQ(run("track --in " + gt + " --out " + est), 2);
  EXPECT_NE(err().find("need the frame rate: --rate HZ"), std::string::npos) << err();
  EXPECT_EQ(run("track --in " + gt + " --out " + est + " --rate 30 --quiet"), 0) << err();
  EXPECT_EQ(run("track --in " + gt + " --out " + est + " --rate 30 --object p"), 2);
  // Scored against itself (its frames only): the rate times the truth's frame numbers too.
  ASSERT_EQ(run("evaluate --in " + gt + " --truth " + gt + " --rate 30 --no-fill --estimators " +
                "cvkf --seeds 1"),
            0)
      << err();
}

// KITTI tracking labels in the camera's frame (x right, y down, z forward): a car drives past
// 10 m ahead, hiding a pedestrian standing 15 m ahead for frames 15 to 25, whose labels are left
// out there. The OPF holds the pedestrian where it stands through the gap.
TEST_F(OpfProgram, KittiTrackingLabelsTrackEachIdThroughAnOcclusion) {
  const fs::path labels = dir_ / "0000.txt";
  {
    std::ofstream out(labels);
    out << "0 -1 DontCare -1 -1 -10 219 188 245 218 -1000 -1000 -1000 -10 -1 -1 -1\n";
    for (int k = 0; k < 40; ++k) {
      out << k << " 0 Car 0 0 0 0 0 0 0 1.5 1.8 4.4 " << -8.0 + 0.4 * k << " 1.6 10 0\n";
      if (k < 15 || k > 25) out << k << " 1 Pedestrian 0 0 0 0 0 0 0 1.7 0.6 0.8 0 1.6 15 1.57\n";
    }
  }
  std::ofstream(dir_ / "up.yaml") << "opf:\n  dynamics:\n    up: [0, -1, 0]\n";
  const std::string est = (dir_ / "est.csv").string();
  ASSERT_EQ(run("track --in " + labels.string() + " --out " + est + " --rate 10 --camera 0,0,0 " +
                "--config " + (dir_ / "up.yaml").string() + " --particles 1000 --quiet"),
            0)
      << err();
  std::size_t hidden = 0;
  for (const EstimateRecord& row : read_estimate_csv(est)) {
    if (row.object != "1" || row.hypothesis != 0) continue;
    hidden += row.mode.rfind("measured", 0) == 0 ? 0 : 1;
    // Its centre, half its 1.7 m above the bottom at y = 1.6: within half the 10 mm noise the
    // filters are told, measured or not (the labels are exact).
    EXPECT_LT((translation_of(row.pose) - Eigen::Vector3d(0.0, 0.75, 15.0)).norm(), 0.005)
        << row.t << " " << row.mode;
  }
  EXPECT_EQ(hidden, 11u);
  // Scored against labels that keep the pedestrian through the gap: the rate times the truth's
  // frame numbers too (it was dropped with the truth's gap filling, and the truth refused).
  {
    std::ofstream truth(dir_ / "truth.txt");
    for (int k = 0; k < 40; ++k)
      truth << k << " 0 Car 0 0 0 0 0 0 0 1.5 1.8 4.4 " << -8.0 + 0.4 * k << " 1.6 10 0\n"
            << k << " 1 Pedestrian 0 2 0 0 0 0 0 1.7 0.6 0.8 0 1.6 15 1.57\n";
  }
  ASSERT_EQ(run("evaluate --in " + labels.string() + " --truth " + (dir_ / "truth.txt").string() +
                " --rate 10 --camera 0,0,0 --config " + (dir_ / "up.yaml").string() +
                " --estimators opf,cvkf --seeds 1 --particles 1000 --out " +
                (dir_ / "scores.csv").string()),
            0)
      << err();
  EXPECT_NE(read(dir_ / "scores.csv").find("opf"), std::string::npos);
  // Frame numbers need the rate; ids name the objects.
  EXPECT_EQ(run("track --in " + labels.string() + " --out " + est), 2);
  EXPECT_NE(err().find("a KITTI tracking file's frame numbers need the frame rate: --rate HZ"),
            std::string::npos)
      << err();
  EXPECT_EQ(run("track --in " + labels.string() + " --out " + est + " --rate 10 --object p"), 2);
}

TEST_F(OpfProgram, ALogThatWouldBeReadWrongIsRefusedOrWarnedAbout) {
  EXPECT_EQ(run("track --in " + kExampleLog + " --out x.csv --columns object=t"), 2);
  EXPECT_NE(err().find("'object=t' reads object from the column that t reads too"),
            std::string::npos)
      << err();
  EXPECT_EQ(run("track --in " + kExampleLog + " --out x.csv --format tum --columns x=px"), 2);
  // The example log with each quaternion written w first under the same header.
  const fs::path w_first = dir_ / "w_first.csv";
  {
    std::ifstream in(kExampleLog);
    std::ofstream out(w_first);
    std::string line;
    std::getline(in, line);  // t,object,x,y,z,qx,qy,qz,qw,source
    out << "t,object,x,y,z,qx,qy,qz,qw\n";
    while (std::getline(in, line)) {
      std::vector<std::string> f;
      std::stringstream fields(line);
      for (std::string field; std::getline(fields, field, ',');) f.push_back(field);
      if (f.size() < 9 || f[2].empty()) {
        out << f.at(0) << ',' << f.at(1) << ",,,,,,,\n";
        continue;
      }
      out << f[0] << ',' << f[1] << ',' << f[2] << ',' << f[3] << ',' << f[4] << ',' << f[8] << ','
          << f[5] << ',' << f[6] << ',' << f[7] << '\n';
    }
  }
  const std::string est = (dir_ / "est.csv").string();
  ASSERT_EQ(run("track --in " + w_first.string() + " --out " + est + " --estimator cvkf"), 0);
  EXPECT_NE(err().find("warning: " + w_first.string() + ": object 'mug': its quaternions"),
            std::string::npos)
      << err();
  ASSERT_EQ(run("track --in " + w_first.string() + " --out " + est +
                " --estimator cvkf --columns qw=qx,qx=qy,qy=qz,qz=qw"),
            0);
  EXPECT_EQ(err().find("its quaternions"), std::string::npos) << err();
}

}  // namespace
}  // namespace opf
