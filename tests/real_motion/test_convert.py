"""The real-motion converter on a few inline lines of every raw format, with known answers."""

import importlib.util
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[2]
_spec = importlib.util.spec_from_file_location(
    "convert", ROOT / "experiments" / "real_motion" / "convert.py")
convert = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(convert)


def write(path, text):
    path.write_text(text, encoding="utf-8")
    return path


def read_log(path):
    """(t, object, 7 pose numbers) rows of a written log."""
    lines = path.read_text(encoding="utf-8").splitlines()
    assert lines[0] == convert.HEADER
    rows = [line.split(",") for line in lines[1:]]
    return (np.array([float(r[0]) for r in rows]), [r[1] for r in rows],
            np.array([[float(v) for v in r[2:]] for r in rows]))


def test_tum_times_from_zero_and_quaternion_order(tmp_path):
    f = write(tmp_path / "a.txt", "# ground truth\n# timestamp tx ty tz qx qy qz qw\n"
              "100.5 1 2 3 0 0 0 1\n100.6 1 2 4 0 0 1 0\n")
    t, p, q = convert.read_tum(f)
    convert.write_log(tmp_path / "o.csv", "cam", t - t[0], p, q)
    tt, obj, pose = read_log(tmp_path / "o.csv")
    assert tt.tolist() == [0.0, pytest.approx(0.1)] and obj == ["cam", "cam"]
    assert pose[1].tolist() == [1, 2, 4, 0, 0, 1, 0]


def test_euroc_w_first_quaternion_is_reordered(tmp_path):
    f = write(tmp_path / "data.csv", "#timestamp [ns],p_x,p_y,p_z,q_w,q_x,q_y,q_z,v_x\n"
              "1403636580838555648,4.6,-1.7,0.7,0.5,0.1,0.2,0.3,9\n"
              "1403636580843555584,4.7,-1.7,0.7,0.5,0.1,0.2,0.3,9\n")
    t, p, q = convert.read_euroc(f)
    assert t.tolist() == [0.0, pytest.approx(0.004999936, abs=1e-12)]  # integer ns kept exact
    assert q[0].tolist() == [0.1, 0.2, 0.3, 0.5] and p[1].tolist() == [4.7, -1.7, 0.7]


def test_kitti_matrix_to_quaternion_and_10hz_times(tmp_path):
    # 90 degrees about z: x -> y.
    f = write(tmp_path / "00.txt", "1 0 0 0 0 1 0 0 0 0 1 0\n0 -1 0 5 1 0 0 6 0 0 1 7\n")
    t, p, q = convert.read_kitti(f)
    assert t.tolist() == [0.0, 0.1] and p[1].tolist() == [5, 6, 7]
    assert q[1] == pytest.approx([0, 0, np.sqrt(0.5), np.sqrt(0.5)])
    # A half turn about x exercises the branch for a negative trace.
    r = np.diag([1.0, -1.0, -1.0])
    assert abs(convert.matrix_to_quaternion(r)) == pytest.approx([1, 0, 0, 0])
    times = write(tmp_path / "times.txt", "0.0\n0.25\n")
    assert convert.read_kitti(f, times)[0].tolist() == [0.0, 0.25]


def test_gap_windows_hide_exactly_start_to_start_plus_length():
    t = np.arange(0, 301) / 30.0  # 0 .. 10 s at 30 Hz
    hidden = convert.gap_mask(t, 0.3)
    expected = np.zeros_like(hidden)
    for start in (2.0, 4.5, 7.0, 9.5):
        expected |= (t >= start) & (t < start + 0.3)
    assert (hidden == expected).all()
    assert hidden[60] and not hidden[59] and not hidden[69] and hidden[68]  # [2.0, 2.3)


def test_longer_gaps_leave_one_and_a_half_seconds_seen_between_them():
    t = np.arange(0, 601) / 30.0  # 0 .. 20 s at 30 Hz
    assert convert.gap_period(1.0) == 2.5 and convert.gap_period(4.0) == 5.5
    hidden = convert.gap_mask(t, 4.0)
    expected = np.zeros_like(hidden)
    for start in (2.0, 7.5, 13.0, 18.5):
        expected |= (t >= start) & (t < start + 4.0)
    assert (hidden == expected).all()
    assert convert.parse_gaps("2,4") == (2.0, 4.0)
    for bad in ("", "2,x", "0", "-1", "31", "2,2"):
        with pytest.raises(convert.ConvertError, match="--gaps"):
            convert.parse_gaps(bad)


def test_missed_frames_are_seeded_independent_draws_after_the_first(tmp_path):
    t = np.arange(0, 3001) / 30.0
    p = np.column_stack([t, np.zeros_like(t), np.ones_like(t)])
    q = np.tile([0.0, 0.0, 0.0, 1.0], (len(t), 1))
    entries = convert.convert_trajectory("seq", "handheld", t, p, q, ["native"], tmp_path, 7,
                                         missed=0.3)
    assert [e[3] for e in entries] == ["missed0.3"] and entries[0][4] == "seq_native_missed0.3.csv"
    lt, _, _ = read_log(tmp_path / "seq_native_missed0.3.csv")
    seen = np.round(lt * 30).astype(int)
    assert seen[0] == 0 and entries[0][7] == len(t) - len(seen)
    assert 0.27 < entries[0][7] / (len(t) - 1) < 0.33  # binomial sd 0.008
    # Runs of missed frames as independent draws make them: two in a row about 0.3 of the time.
    missed = np.setdiff1d(np.arange(len(t)), seen)
    assert 0.25 < np.isin(missed + 1, missed).mean() < 0.35
    first = (tmp_path / "seq_native_missed0.3.csv").read_bytes()
    convert.convert_trajectory("seq", "handheld", t, p, q, ["native"], tmp_path, 7, missed=0.3)
    assert (tmp_path / "seq_native_missed0.3.csv").read_bytes() == first
    assert convert.parse_missed("0.3") == 0.3
    for bad in ("0", "1", "-0.1", "x", "nan"):
        with pytest.raises(convert.ConvertError, match="--missed"):
            convert.parse_missed(bad)


def test_noise_on_visible_rows_only_truth_clean_and_seeded(tmp_path):
    t = np.arange(0, 181) / 30.0
    p = np.column_stack([t, np.zeros_like(t), np.ones_like(t)])
    q = np.tile([0.0, 0.0, 0.0, 1.0], (len(t), 1))
    entries = convert.convert_trajectory("seq", "handheld", t, p, q, ["native"], tmp_path, 7)
    tt, _, truth = read_log(tmp_path / "seq_native_truth.csv")
    assert np.allclose(truth[:, :3], p) and np.allclose(truth[:, 3:], q)  # noise-free truth
    lt, _, log = read_log(tmp_path / "seq_native_0.6.csv")
    assert set(np.round(lt * 30).astype(int)) == set(np.nonzero(~convert.gap_mask(t, 0.6))[0])
    error = log[:, :3] - p[np.round(lt * 30).astype(int)]
    assert 0.001 < error.std() < 0.003  # 2 mm per axis
    assert np.allclose(np.linalg.norm(log[:, 3:], axis=1), 1)
    assert entries[1][6:8] == (181, int(convert.gap_mask(t, 0.6).sum()))
    first = (tmp_path / "seq_native_0.6.csv").read_bytes()
    convert.convert_trajectory("seq", "handheld", t, p, q, ["native"], tmp_path, 7)
    assert (tmp_path / "seq_native_0.6.csv").read_bytes() == first
    convert.convert_trajectory("seq", "handheld", t, p, q, ["native"], tmp_path, 8)
    assert (tmp_path / "seq_native_0.6.csv").read_bytes() != first


def test_resampling_interpolates_linear_motion_exactly():
    t = np.array([0.0, 0.013, 0.05, 0.071, 0.1, 0.142, 0.2])  # irregular clock
    p = np.column_stack([2 * t, -t, np.full_like(t, 3.0)])
    angle = 0.5 * t  # constant rate about z
    q = np.column_stack([np.zeros((len(t), 2)), np.sin(angle / 2), np.cos(angle / 2)])
    tk, pk, qk = convert.resample(t + 50.0, p, q)
    assert np.allclose(tk, np.arange(7) / 30.0)
    assert np.allclose(pk, np.column_stack([2 * tk, -tk, np.full_like(tk, 3.0)]), atol=1e-9)
    assert np.allclose(qk[:, 2], np.sin(0.25 * tk), atol=1e-9)


def test_quaternion_sign_is_made_continuous():
    q = np.array([[0, 0, 0, 2.0], [0, 0, 0.1, -1.0]])
    out = convert.continuous(q)
    assert out[0].tolist() == [0, 0, 0, 1] and out[1][3] > 0


MOT = "".join(f"{f},7,100,200,20,60,1,1,{v}\n" for f, v in zip(
    range(1, 61), [1.0] * 40 + [0.1] * 10 + [0.2, 0.3] + [0.9] * 8))


def test_mot_low_visibility_is_hidden_and_foot_point_position(tmp_path):
    f = write(tmp_path / "gt.txt", MOT + "1,8,0,0,1,1,0,1,1\n")  # conf 0: ignored row
    tracks = convert.read_mot(f)
    assert list(tracks) == [7]
    entries = convert.convert_pedestrians("m", "pedestrian", tracks, 30.0, tmp_path, 0)
    assert entries[0][6:8] == (60, 11)  # visibility 0.1 x10 and 0.2 hidden, 0.3 not
    t, obj, pose = read_log(tmp_path / "m_p7_native_truth.csv")
    assert obj[0] == "p7" and t[1] == pytest.approx(1 / 30)
    assert pose[0][:3].tolist() == [0.11, 0.26, 0]  # centre u, bottom v, in 1 mm per px
    lt, _, log = read_log(tmp_path / "m_p7_native_occluded.csv")
    assert len(lt) == 49 and not np.any((lt > 1.3) & (lt < 1.7))
    assert (log[:, 2] == 0).all() and (log[:, 3:] == [0, 0, 0, 1]).all()


def test_mot_tracks_need_a_visible_start_and_a_real_occlusion(tmp_path):
    short = "".join(f"{f},3,0,0,10,10,1,1,{0.1 if f > 10 else 1}\n" for f in range(1, 30))
    tracks = convert.read_mot(write(tmp_path / "gt.txt", MOT + short))
    assert list(convert.occluded_tracks(tracks, 30.0)) == [7]  # track 3 hides after 0.3 s


@pytest.mark.parametrize("reader,text,message", [
    (convert.read_tum, "# c\n1 2 3 4 0 0 0 1\n2 2 3 x 0 0 0 1\n", "x.txt:3: field tz: not a number"),
    (convert.read_tum, "1 2 3 4 0 0 0\n", "x.txt:1: expected 8 fields, found 7"),
    (convert.read_euroc, "#h\n1,2,3,4,1,0,0,0\n2,2,3,4,1,0,0,0\n2,2,3,4,1,0,0,0\n",
     "x.txt:4: field timestamp: time not increasing"),
    (convert.read_kitti, "1 0 0 0 0 1 0 0 0 0 1 nan\n", "x.txt:1: field t2: not finite"),
    (convert.read_mot, "1,1,2,3,4,5,1,1,vis\n", "x.txt:1: field visibility: not a number"),
])
def test_malformed_line_names_file_line_and_field(tmp_path, reader, text, message):
    f = write(tmp_path / "x.txt", text)
    with pytest.raises(convert.ConvertError, match=message):
        reader(f, label="x.txt")


def test_cli_writes_index_and_is_deterministic(tmp_path):
    raw = tmp_path / "raw"
    raw.mkdir()
    write(raw / "a.txt", "".join(f"{i / 100} {i / 100} 0 0 0 0 0 1\n" for i in range(600)))
    write(raw / "gt.txt", MOT)
    write(raw / "seqinfo.ini", "[Sequence]\nframeRate=30\n")
    manifest = write(tmp_path / "sequences.csv", "name,kind,format,file,aux,rates\n"
                     "a,handheld,tum,raw/a.txt,,native;30hz\n"
                     "m,pedestrian,mot,raw/gt.txt,raw/seqinfo.ini,native\n")
    for out in ("o1", "o2"):
        assert convert.main(["--out", str(tmp_path / out), "--manifest", str(manifest)]) == 0
    files = sorted(p.name for p in (tmp_path / "o1").iterdir())
    assert all((tmp_path / "o1" / n).read_bytes() == (tmp_path / "o2" / n).read_bytes()
               for n in files)
    index = (tmp_path / "o1" / "index.csv").read_text().splitlines()
    assert len(index) == 1 + 6 + 1 and index[-1].startswith("m,pedestrian,native,occluded,")
    assert "a_30hz_1.csv" in files and "a_native_truth.csv" in files
    # Other gap lengths: a log per length, named by it; the truths are the same.
    assert convert.main(["--out", str(tmp_path / "o3"), "--manifest", str(manifest), "--gaps",
                         "2.5"]) == 0
    long_gaps = sorted(p.name for p in (tmp_path / "o3").iterdir())
    assert "a_30hz_2.5.csv" in long_gaps and "a_30hz_1.csv" not in long_gaps
    assert ((tmp_path / "o3" / "a_native_truth.csv").read_bytes() ==
            (tmp_path / "o1" / "a_native_truth.csv").read_bytes())
