"""The Python module against the C++ library (docs/python.md): run() with init files and both
coordinate systems, the segments array as pandas-ready numpy, events, variables, AlarmError with
number, file and line, and Stream fed line by line giving what run() gives."""
import os
import pathlib

import numpy as np
import pytest

import ncoffset

SOURCE = pathlib.Path(os.environ.get("NCOFFSET_SOURCE", pathlib.Path(__file__).parents[2]))
EXAMPLES = SOURCE / "examples"

# One corner with G41 (tool radius 4 from TOOLS below): the path the issue reported differing
# between block-by-block runText calls and one call. Hand values: the tool runs 4 mm left of the
# contour X0..X30 on Y0, then up X30 Y0..Y20; G451 off, G450 default: the outside corner at
# X30 Y0 seen from the left side is an inside corner (the contour turns left), so the
# equidistants meet at X26 Y4: the first element ends there.
TOOLS = "$TC_DP1[1,1]=120\n$TC_DP3[1,1]=100\n$TC_DP6[1,1]=4\nM17\n"
CORNER = "T1 D1 M6\nG17 G90 G0 X-10 Y4\nG41 G1 X0 Y4 F500\nX30 Y4\nX26 Y30\nG40 G0 X-10 Y40\nM30\n"
CORNER = "T1 D1 M6\nG17 G90 G1 F500 X0 Y0\nG41 X10 Y0\nX30 Y0\nX30 Y20\nG40 X40 Y30\nM30\n"


@pytest.fixture
def tools(tmp_path):
    p = tmp_path / "TOOLS.INI"
    p.write_text(TOOLS)
    return p


def test_run_segments_are_a_structured_array(tools, tmp_path):
    r = ncoffset.run("CORNER.MPF", init=[tools], coords="wcs", text=CORNER)
    seg = r.segments
    assert isinstance(seg, np.ndarray)
    assert seg.dtype.names[:3] == ("line", "file", "motion")
    assert r.alarm is None and r.ended
    # The element of X30 Y0 (line 4) ends where the equidistants of Y=0 (at Y=4) and X=30 (at
    # X=26) meet: the inside corner X26 Y4 (W1 2.3, intersection of the equidistants).
    row = seg[seg["line"] == 4][-1]
    assert row["x"] == pytest.approx(26) and row["y"] == pytest.approx(4)
    assert row["motion"] == 1 and row["has_feed"] and row["feed"] == 500


def test_mcs_adds_the_tool_length(tools):
    text = "T1 D1 M6\nG17 G90 G0 X0 Y0 Z10\nM30\n"
    wcs = ncoffset.run("L.MPF", init=[tools], coords="wcs", text=text).segments
    mcs = ncoffset.run("L.MPF", init=[tools], coords="mcs", text=text).segments
    # $TC_DP3 = 100 (length 1 along Z with G17): the carrier is 100 mm above the tool tip.
    assert mcs["z"][-1] - wcs["z"][-1] == pytest.approx(100)


def test_start_position_and_a_continuous_path_across_a_tool_change(tools):
    # Hand values: the carrier starts at (0, 0, 500) MCS; G0 Z50 without a tool moves it to Z50.
    # T1 D1 (L1 = 100 along Z, MD22550 = 0: active at once) moves nothing; G0 Z5 takes the
    # length up: the carrier runs from Z50 to Z5 + 100 = 105 (FM-W1: the offset is traversed
    # with the next programmed motion of the axis), not from Z150. In WCS the same motion runs
    # from Z50 - 100 = -50 (the new tool's tip under the carrier) to Z5.
    text = "G17 G90 G0 Z50\nT1 D1\nG0 Z5\nM30\n"
    mcs = ncoffset.run("S.MPF", init=[tools], text=text, start=(0, 0, 500)).segments
    assert [tuple(mcs[k][0] for k in ("sx", "sy", "sz"))] == [(0, 0, 500)]
    assert (mcs["sz"][1], mcs["z"][1]) == (pytest.approx(50), pytest.approx(105))
    wcs = ncoffset.run("S.MPF", init=[tools], text=text, coords="wcs", start=(0, 0, 500)).segments
    assert (wcs["sz"][1], wcs["z"][1]) == (pytest.approx(-50), pytest.approx(5))
    # Without start=: machine zero; the stream takes the same option.
    assert ncoffset.run("S.MPF", init=[tools], text=text).segments["sz"][0] == 0
    s = ncoffset.Stream(init=[tools], start=(1, 2, 3))
    part = s.feed(text)
    rows = np.concatenate([part.segments, s.finish().segments])
    assert (rows["sx"][0], rows["sy"][0], rows["sz"][0]) == (1, 2, 3)


def test_frame_change_is_an_event_and_the_wcs_start_is_the_point_in_the_new_frame(tmp_path):
    # Hand values: G54 ($P_UIFR[1] X100 Y50) after G0 X0 Y0 Z20 (MCS 0,0,20): the event with
    # offset (100, 50, 0) comes before the segment of line 2, whose WCS start is MCS 0,0,20 in
    # G54: X-100 Y-50 Z20 (the carrier does not jump: in MCS it starts at 0,0,20).
    ini = tmp_path / "FR.INI"
    ini.write_text("$P_UIFR[1,X,TR]=100\n$P_UIFR[1,Y,TR]=50\nM17\n")
    text = "G0 X0 Y0 Z20\nG54 G0 X10\nM30\n"
    r = ncoffset.run("F.MPF", init=[ini], coords="wcs", text=text)
    frames = [e for e in r.events if e["type"] == "frame"]
    assert len(frames) == 1 and frames[0]["segment"] == 1 and frames[0]["line"] == 2
    assert frames[0]["offset"] == (100, 50, 0)
    seg = r.segments
    assert (seg["sx"][1], seg["sy"][1], seg["sz"][1]) == (-100, -50, 20)
    mcs = ncoffset.run("F.MPF", init=[ini], text=text).segments
    assert (mcs["sx"][1], mcs["sy"][1], mcs["sz"][1], mcs["x"][1]) == (0, 0, 20, 110)


def test_pandas_takes_the_array(tools):
    pd = pytest.importorskip("pandas")
    r = ncoffset.run("CORNER.MPF", init=[tools], coords="wcs", text=CORNER)
    df = pd.DataFrame(r.segments)
    assert list(df.columns[:3]) == ["line", "file", "motion"] and len(df) == len(r.segments)


def test_events_and_variables(tools):
    text = "DEF REAL DEPTH=2.5\nR7=3\nT1 D1 M6\nS1200 M3\nG4 F1.5\nG1 X10 F300\nM5\nM30\n"
    r = ncoffset.run("EV.MPF", init=[tools], text=text)
    types = [e["type"] for e in r.events]
    assert types == ["tool", "tool", "tool", "m", "spindle", "dwell", "feed", "m"]
    tool = r.events[0]
    assert tool["word"] == "T" and tool["radius"] == 4 and tool["length"] == (0, 0, 100)
    assert r.events[3]["number"] == 3 and r.events[4]["speed"] == 1200
    assert r.events[5]["seconds"] == 1.5
    # The feed event comes before the segment of its block, M5 after it.
    assert r.events[6]["segment"] == 0 and r.events[7]["segment"] == 1
    assert r.variables["R"]["7"] == 3 if "R" in r.variables else True
    assert "DEPTH" in str(r.variables)


def test_alarm_is_an_exception_with_number_file_and_line():
    with pytest.raises(ncoffset.AlarmError) as e:
        ncoffset.run("BAD.MPF", text="G1 X10 F100\nG1 X20\nR1=1/0\nM30\n")
    assert e.value.number == 14051 and e.value.file == "BAD.MPF" and e.value.line == 3
    assert len(e.value.result.segments) == 2  # what ran before the alarm
    r = ncoffset.run("BAD.MPF", text="R1=1/0\n", raise_on_alarm=False)
    assert r.alarm["number"] == 14051


def test_missing_file_is_an_error():
    with pytest.raises(ValueError):
        ncoffset.run("/nonexistent/P.MPF")


def test_stream_line_by_line_is_the_whole_run(tools):
    whole = ncoffset.run("CORNER.MPF", init=[tools], text=CORNER)
    s = ncoffset.Stream(init=[tools], name="CORNER.MPF")
    parts, events = [], []
    for line in CORNER.splitlines(keepends=True):
        b = s.feed(line)
        parts.append(b.segments)
        events += b.events
    last = s.finish()
    parts.append(last.segments)
    events += last.events
    streamed = np.concatenate(parts)
    assert len(streamed) == len(whole.segments) and (streamed == whole.segments).all()
    strip = lambda evs: [{k: v for k, v in e.items() if k != "segment"} for e in evs]
    assert strip(events) == strip(whole.events)
    assert last.ended


def test_stream_holds_the_corner_until_the_next_block(tools):
    s = ncoffset.Stream(init=[tools], coords="wcs")
    b = s.feed("T1 D1 M6\nG17 G90 G1 F500 X0 Y0\nG41 X10 Y0\nX30 Y0\n")
    # X30 Y0's element stays open while its end may change: it is not written yet.
    assert 4 not in b.segments["line"]
    rest = [s.feed("X30 Y20\n").segments, s.feed("G40 X40 Y30\nM30\n").segments]
    rows = np.concatenate(rest)
    row = rows[rows["line"] == 4]
    # ... and ends on the inside corner X26 Y4, as in one run (the X30/Y4 was wrong).
    assert len(row) == 1 and row["x"][0] == pytest.approx(26) and row["y"][0] == pytest.approx(4)


def test_stream_alarm_raises(tools):
    s = ncoffset.Stream()
    with pytest.raises(ncoffset.AlarmError) as e:
        s.feed("G1 X10 F100\nR1=1/0\n")
    assert e.value.line == 2


def test_example_program_runs():
    r = ncoffset.run(EXAMPLES / "pocket.MPF", init=[EXAMPLES / "tools.INI"])
    assert len(r.segments) > 10
