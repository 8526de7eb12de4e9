"""Tests of the Python package `rolldyn`, its sweeps and their Dask
backend. Run by scripts/test.sh after `cargo test`; the CLI binary to
compare with is $ROLLDYN_CLI (default: target/debug/rolldyn).

The package runs the CLI's own code, so its results must equal the CLI's
exactly: reports as dicts equal to `--json`, run summaries equal but for the
wall time, time series bit-identical to the CLI's Parquet file.
"""

import json
import os
import pickle
import signal
import subprocess
import threading
from pathlib import Path

import numpy as np
import pyarrow as pa
import pyarrow.parquet as pq
import pytest

import rolldyn

REPO = Path(__file__).resolve().parents[3]
CLI = Path(os.environ.get("ROLLDYN_CLI", REPO / "target" / "debug" / "rolldyn"))


def cli_json(*args):
    if not CLI.exists():
        pytest.skip(f"no rolldyn binary at {CLI} (set ROLLDYN_CLI)")
    out = subprocess.run([str(CLI), *args], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    return json.loads(out.stdout) if out.stdout.strip() else None


def cli(*args):
    if not CLI.exists():
        pytest.skip(f"no rolldyn binary at {CLI} (set ROLLDYN_CLI)")
    out = subprocess.run([str(CLI), *args], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    return out


def without_wall(summary):
    return {k: v for k, v in summary.items() if k != "wall_time_s"}


# --- cases ---------------------------------------------------------------


def test_presets_are_the_clis():
    listed = {p["name"]: p["summary"] for p in cli_json("presets", "--json")}
    assert rolldyn.presets() == listed


def test_case_constructors_agree():
    text = (REPO / "examples" / "seed000" / "case.toml").read_text()
    from_file = rolldyn.Case.load(REPO / "examples" / "seed000" / "case.toml")
    from_text = rolldyn.Case.from_toml(text)
    assert from_file.describe()["geometry"] == from_text.describe()["geometry"]
    default = rolldyn.Case.default()
    assert default.source == rolldyn.DEFAULT_SOURCE
    assert default.describe() == cli_json("check", "--json")
    # A preset is its case-file text, as `rolldyn new --preset` prints it.
    preset = rolldyn.Case.preset("7008C").describe()
    assert preset["source"] == "preset 7008C"
    assert preset["geometry"] == default.describe()["geometry"]


def test_set_validates_at_once_and_leaves_the_case_unchanged():
    case = rolldyn.Case.preset("6304")
    with pytest.raises(rolldyn.CaseError) as e:
        case.set("operating.speed", "fast")
    # The CLI's located message: key, value, rule.
    assert "operating.speed" in str(e.value)
    assert "fast" in str(e.value)
    # Named as Python gave it, not as the CLI's --set.
    assert "Case.set" in str(e.value) and "--set" not in str(e.value)
    assert case.overrides == []
    with pytest.raises(rolldyn.CaseError, match="bearing.ball_count"):
        case.set("bearing.ball_count", -3)
    assert case.set("speed", "3000 rpm").set("bearing.ball_count", 8) is case
    assert case.overrides == ["operating.speed=3000 rpm", "bearing.ball_count=8"]
    assert case.describe()["geometry"]["ball_count"] == 8


def test_values_cross_typed_and_replay_on_the_command_line(tmp_path):
    spall = [{"position": "90 deg", "length": "0.3 mm", "depth": "20 um"}]
    case = rolldyn.Case.preset("6205").set("surface.outer.spall", spall)
    case.set("cage.pocket_friction", np.float64(0.05)).set("bearing.ball_count", "9")
    # Typed as they cross into the engine: a NumPy scalar as a float, a
    # string on its own read as `--set` reads it ("9" is the integer 9).
    assert case.values == [("surface.outer.spall", spall), ("cage.pocket_friction", 0.05),
                           ("bearing.ball_count", "9")]
    assert case.overrides == [
        'surface.outer.spall=[{ depth = "20 um", length = "0.3 mm", position = "90 deg" }]',
        "cage.pocket_friction=0.05", "bearing.ball_count=9"]
    # `overrides` gives the same case on the command line.
    preset = tmp_path / "6205.toml"
    preset.write_text(case.text)
    sets = [a for o in case.overrides for a in ("--set", o)]
    expected = cli_json("check", str(preset), *sets, "--json")
    described = case.describe()
    assert {k: v for k, v in described.items() if k != "source"} == \
        {k: v for k, v in expected.items() if k != "source"}
    # A value of no case type, or not finite, is refused, naming its key.
    with pytest.raises(rolldyn.CaseError, match="operating.speed"):
        case.set("operating.speed", None)
    with pytest.raises(rolldyn.CaseError, match="cage.pocket_friction"):
        case.set("cage.pocket_friction", float("nan"))
    # The constructor takes the values as pairs, a mapping or --set texts.
    same = rolldyn.Case(case.source, case.text, case.overrides)
    assert same.describe() == described
    assert rolldyn.Case(case.source, case.text, [("speed", "3000 rpm")]).values == \
        [("operating.speed", "3000 rpm")]
    with pytest.raises(rolldyn.CaseError, match="KEY=VALUE"):
        rolldyn.Case(case.source, case.text, ["bearing.ball_count"])
    # The run records the values typed; the CLI resumes and extends it.
    rolldyn.run(case, duration="1 ms", output=tmp_path / "py")
    record = json.loads((tmp_path / "py" / "run.json").read_text())
    assert record["overrides"]["values"][0] == {"key": "surface.outer.spall", "value": spall}
    cli("run", "--resume", str(tmp_path / "py"), "--until", "2 ms")
    summary = json.loads((tmp_path / "py" / "summary.json").read_text())
    assert summary["status"] == "completed" and summary["simulated_time_s"] == pytest.approx(2e-3)


def test_unknown_preset_names_the_choices():
    with pytest.raises(rolldyn.CaseError, match="7008C"):
        rolldyn.Case.preset("nope")


def test_catalogue_is_the_clis():
    # The table and a bearing's case text, as `rolldyn catalogue` and
    # `rolldyn new --bearing` give them.
    assert rolldyn.catalogue("72") == cli_json("catalogue", "--series", "72", "--json")
    case = rolldyn.Case.catalogue("6205", clearance="C3")
    assert case.text.rstrip() == cli("new", "--bearing", "6205", "--clearance", "C3").stdout.rstrip()
    geometry = case.describe()["geometry"]
    assert geometry["ball_count"] == 9
    with pytest.raises(rolldyn.CaseError, match="contact angle code"):
        rolldyn.Case.catalogue("7210")
    with pytest.raises(rolldyn.CaseError, match="C2, CN, C3 or C4"):
        rolldyn.Case.catalogue("6205", clearance="C9")


def test_cases_pickle():
    case = rolldyn.Case.preset("7218B").set("speed", "2000 rpm")
    assert pickle.loads(pickle.dumps(case)) == case


# --- reports equal the CLI's --json ------------------------------------------


def test_frequencies_equal_the_cli():
    case = rolldyn.Case.preset("6205").set("speed", "1797 rpm")
    cli("presets")  # skips without a binary
    # The preset's text through standard input, as the Python case holds it.
    out = subprocess.run([str(CLI), "frequencies", "--json", "-", "--speed", "1797 rpm"],
                         input=rolldyn._rolldyn.preset_text("6205"), capture_output=True,
                         text=True)
    assert out.returncode == 0, out.stderr
    expected = json.loads(out.stdout)
    assert rolldyn.frequencies(case) == expected
    assert rolldyn.frequencies(case, angle="10 deg") != expected


def test_contact_ball_on_flat():
    c = rolldyn.contact("100 N", ball_on_flat="12.7 mm")
    assert c == cli_json("contact", "--json", "--load", "100 N", "--ball-on-flat", "12.7 mm")
    assert c["ellipticity"] == pytest.approx(1.0, rel=1e-9)
    assert c["semi_major_m"] == pytest.approx(c["semi_minor_m"], rel=1e-9)
    with pytest.raises(rolldyn.CaseError, match="--load"):
        rolldyn.contact("-5 N")


def test_quasistatic_equals_the_cli():
    case = rolldyn.Case.default().set("speed", "6000 rpm")
    expected = cli_json("quasistatic", "--json", "--speed", "6000 rpm", "--control", "inner")
    assert rolldyn.quasistatic(case, control="inner") == expected
    with pytest.raises(rolldyn.CaseError, match="outer, inner, harris or traction"):
        rolldyn.quasistatic(case, control="sideways")


def test_reports_are_typed_objects():
    """Reports have the CLI's keys as attributes: vectors and matrices as
    NumPy arrays, rows as a Table with NumPy columns, the same numbers."""
    qs = rolldyn.quasistatic(rolldyn.Case.default())
    assert isinstance(qs, rolldyn.QuasiStaticResult)
    assert qs.cage_speed_rpm == qs["cage_speed_rpm"]
    k = qs.stiffness_matrix
    assert isinstance(k, np.ndarray) and k.shape == (5, 5)
    assert k[0, 0] == qs["stiffness_matrix"][0][0]
    assert qs.displacement[0] == qs["axial_displacement_m"]
    balls = qs.balls
    assert isinstance(balls, rolldyn.Table) and len(balls) == 22
    loads = balls.load_inner_n
    assert isinstance(loads, np.ndarray) and loads.shape == (22,)
    assert loads[3] == qs["balls"][3]["load_inner_n"] == balls[3].load_inner_n
    assert "load_outer_n" in balls.columns and "load_outer_n" in dir(balls)
    assert qs.rating_life.basic_rating_life_h == qs["rating_life"]["basic_rating_life_h"]
    # None (no value) is NaN in a column, None as an attribute.
    assert qs.rating_life.contamination_factor is None
    with pytest.raises(AttributeError, match="no 'nope'"):
        qs.nope
    with pytest.raises(AttributeError, match="read-only"):
        qs.cage_speed_rpm = 1.0
    again = pickle.loads(pickle.dumps(qs))
    assert type(again) is rolldyn.QuasiStaticResult and again == qs
    assert isinstance(rolldyn.power(), rolldyn.PowerResult)
    f = rolldyn.frequencies()
    assert isinstance(f, rolldyn.Frequencies) and f == f.to_dict()


def _declared(cls):
    """A report class's declared fields: name -> the types an attribute
    may have (Optional adds None)."""
    import typing
    kinds = {"float": (float, int), "int": (int,), "str": (str,), "bool": (bool,),
             "Report": (rolldyn.Report,), "Table": (rolldyn.Table,), "np.ndarray": (np.ndarray,),
             "list": (list,)}
    out = {}
    for name, annotation in cls.__annotations__.items():
        text = annotation if isinstance(annotation, str) else str(annotation)
        optional = text.startswith("Optional[")
        inner = text[len("Optional["):-1] if optional else text
        if inner.startswith("Union["):
            inner = inner[len("Union["):-1]
        types = tuple(t for part in inner.split(", ") for t in kinds[part])
        out[name] = types + ((type(None),) if optional else ())
    return out


def test_report_classes_declare_their_fields(tmp_path):
    """Every key of a report is a field declared with its type on the
    report's class (scripts/python-report-fields.py writes them), every
    declared field is a key of some report here, and each attribute has
    the declared type: single bearings, a pair, a run of each."""
    pair = rolldyn.Case.load(REPO / "examples" / "spindle_pair" / "case.toml")
    cwru = rolldyn.Case.load(REPO / "examples" / "cwru6205" / "case.toml")
    law = '{ law = "fastsim", friction = 0.1 }'
    flags = dict(load="500 N", rolling_speed="10 m/s", creepages="1e-3,0,2")
    fastsim = rolldyn.Case.default().set("model.traction", law)
    run = rolldyn.run(duration="2 ms", output=tmp_path / "run")
    reports = {
        rolldyn.QuasiStaticResult: [rolldyn.quasistatic(), rolldyn.quasistatic(pair),
                                    rolldyn.quasistatic(cwru)],
        rolldyn.PowerResult: [rolldyn.power(), rolldyn.power(pair), rolldyn.power(cwru)],
        rolldyn.ThermalResult: [rolldyn.thermal(), rolldyn.thermal(pair),
                                rolldyn.thermal(transient="10 s")],
        rolldyn.Frequencies: [rolldyn.frequencies(), rolldyn.frequencies(cwru)],
        rolldyn.ContactResult: [rolldyn.contact("500 N")],
        rolldyn.TractionResult: [rolldyn.traction(**flags),
                                 rolldyn.traction(fastsim, method="exact", cells="8", **flags),
                                 rolldyn.traction(fastsim, method="table", **flags)],
        rolldyn.SpectrumResult: [run.spectrum("cage_speed_rpm")],
        rolldyn.Summary: [run.summary,
                          rolldyn.run(pair.set("output.sample_rate", "5 kHz"), "2 ms").summary],
    }
    for cls, results in reports.items():
        declared = _declared(cls)
        seen = set()
        for result in results:
            assert isinstance(result, cls)
            for key in result:
                assert key in declared, f"{cls.__name__}.{key} is not declared"
                value = getattr(result, key)
                assert isinstance(value, declared[key]), \
                    f"{cls.__name__}.{key}: {type(value).__name__}, declared {declared[key]}"
            seen |= set(result)
        null_only = {k for k, t in declared.items() if k not in seen}
        assert not null_only, f"{cls.__name__} declares fields no report has: {null_only}"
    assert isinstance(run.summary, dict) and run.summary.mean_cage_speed_rpm == \
        run.summary["mean_cage_speed_rpm"]


def test_bearing_set_equals_the_cli(tmp_path):
    case = rolldyn.Case.load(REPO / "examples" / "spindle_pair" / "case.toml")
    path = str(REPO / "examples" / "spindle_pair" / "case.toml")
    result = rolldyn.quasistatic(case)
    assert result == cli_json("quasistatic", path, "--json")
    assert result["arrangement"]["kind"] == "back_to_back"
    assert len(result["arrangement"]["bearings"]) == 2
    cli("quasistatic", path, "--sweep", "speed=0rpm..10000rpm/3", "-o", str(tmp_path))
    expected = json.loads((tmp_path / "sweep.json").read_text())
    rows = rolldyn.quasistatic_sweep(case, {"speed": "0rpm..10000rpm/3"})
    assert rows.rows == expected


def test_quasistatic_sweep_equals_the_cli(tmp_path):
    cli("quasistatic", "--sweep", "speed=0rpm..12000rpm/4", "--sweep", "axial=100N,1kN",
        "-o", str(tmp_path))
    expected = json.loads((tmp_path / "sweep.json").read_text())
    rows = rolldyn.quasistatic_sweep(
        None, {"speed": "0rpm..12000rpm/4", "axial": ["100 N", "1 kN"]})
    assert rows.rows == expected
    assert len(rows) == 8 and all(r["converged"] for r in rows)


# --- runs ----------------------------------------------------------------------


def test_run_equals_the_cli_bit_for_bit(tmp_path):
    cli("run", "--duration", "2 ms", "-o", str(tmp_path / "cli"))
    result = rolldyn.run(duration="2 ms", output=tmp_path / "py")
    expected = json.loads((tmp_path / "cli" / "summary.json").read_text())
    assert without_wall(result.summary) == without_wall(expected)
    assert result.status == "completed"
    cli_table = pq.read_table(tmp_path / "cli" / "timeseries.parquet")
    assert result.timeseries.equals(cli_table)
    # The run directory is the CLI's: `rolldyn run --resume`, `report` and
    # Result.load read it.
    loaded = rolldyn.Result.load(tmp_path / "py")
    assert loaded.timeseries.equals(result.timeseries)
    assert Path(result.report()).is_file()


def test_a_run_says_how_accurate_it_is_and_verify_matches_the_cli(tmp_path):
    result = rolldyn.run(duration="2 ms", output=tmp_path / "py", verify=True)
    accuracy = result.summary["accuracy"]
    assert accuracy["status"] in ("ok", "warning")
    assert accuracy["energy_balance_relative_error"] == result.summary["energy_balance_relative_error"]
    verify = accuracy["verify"]
    assert verify["relative_tolerance"] == pytest.approx(result.summary["relative_tolerance"] / 10)
    assert (tmp_path / "py" / "verify" / "summary.json").is_file()
    keys = {c["key"] for c in verify["changes"]}
    assert "mean_cage_speed_rpm" in keys
    cli("run", "--duration", "2 ms", "--verify", "-o", str(tmp_path / "cli"))
    expected = json.loads((tmp_path / "cli" / "summary.json").read_text())
    changes = lambda s: [(c["key"], c["value"], c["reference"]) for c in s["accuracy"]["verify"]["changes"]]
    assert changes(result.summary) == changes(expected)


def test_channels_are_numpy_arrays_with_units_read_one_at_a_time(tmp_path):
    result = rolldyn.run(duration="5 ms", output=tmp_path)
    # A channel is read from the run's Parquet dataset alone, not the
    # whole series.
    before = pa.total_allocated_bytes()
    speed = result["cage_speed_rpm"]
    assert pa.total_allocated_bytes() - before < 10 * speed.nbytes + 65_536
    assert result._table is None
    assert isinstance(speed, np.ndarray) and speed.dtype == np.float64
    assert speed.unit == "rpm" and speed.name == "cage_speed_rpm"
    assert len(speed) == result.summary["samples"]
    assert result["time_s"].unit == "s"
    assert result.units["time_s"] == "s"
    with pytest.raises(KeyError, match="no such channel"):
        result["nope"]
    # The whole table on demand, and the same values.
    assert np.array_equal(result.timeseries.column("cage_speed_rpm").to_numpy(), speed)
    frame = result.to_pandas()
    assert list(frame.columns) == result.channels
    # Without an output directory the series is read before the temporary
    # directory goes.
    temporary = rolldyn.run(duration="1 ms")
    assert temporary.directory is None
    assert temporary.timeseries.num_rows == temporary.summary["samples"]


def test_the_time_series_reads_as_one_table_with_pyarrow_and_pandas(tmp_path):
    # 40 kHz over 0.1 s: several part files.
    cli("run", "--duration", "0.1 s", "--set", 'output.sample_rate="40 kHz"',
        "-o", str(tmp_path))
    series = tmp_path / "timeseries.parquet"
    assert len(list(series.glob("part-*.parquet"))) > 1
    import pyarrow.dataset as ds
    table = ds.dataset(series, format="parquet").to_table()
    summary = json.loads((tmp_path / "summary.json").read_text())
    assert table.num_rows == summary["samples"]
    assert table.schema.field("cage_speed_rpm").metadata[b"unit"] == b"rpm"
    time = table.column("time_s").to_numpy()
    assert np.all(np.diff(time) > 0)
    assert pq.read_table(series).equals(table)
    pandas = pytest.importorskip("pandas")
    frame = pandas.read_parquet(series)
    assert frame.shape == (table.num_rows, table.num_columns)
    assert frame["time_s"].is_monotonic_increasing


def test_slow_channels_are_found_by_name(tmp_path):
    case = rolldyn.Case.default().set("output.slow_channels", '["power"]') \
        .set("output.slow_rate", "2 kHz")
    result = rolldyn.run(case, duration="2 ms", output=tmp_path)
    assert "power_total_w" in result.channels
    assert "power_total_w" not in result.timeseries.column_names
    power = result["power_total_w"]
    assert power.unit == "W"
    slow = result.slow_timeseries
    assert slow.num_rows == len(power) == 5   # 20 kHz / 2 kHz: samples 0, 10, …, 40
    assert np.array_equal(slow.column("time_s").to_numpy(), result["time_s"][::10])


def test_ctrl_c_stops_a_run_and_keeps_the_partial_result(tmp_path):
    # A shell starts a background job (`.ci/run &`) with SIGINT ignored,
    # and Python then installs no KeyboardInterrupt handler: give it the
    # one an interactive Python has.
    previous = signal.getsignal(signal.SIGINT)
    if previous == signal.SIG_IGN:
        signal.signal(signal.SIGINT, signal.default_int_handler)
    timer = threading.Timer(1.0, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    try:
        with pytest.raises(rolldyn.RunInterrupted) as e:
            rolldyn.run(duration="1 s", output=tmp_path)
    finally:
        timer.join()
        signal.signal(signal.SIGINT, previous)
    result = e.value.result
    assert isinstance(e.value, KeyboardInterrupt)
    assert result.status == "interrupted"
    assert 0 < result.summary["simulated_time_s"] < 1.0
    assert result.timeseries.num_rows == result.summary["samples"]
    # The run directory holds the same, and a checkpoint to resume from.
    on_disk = json.loads((tmp_path / "summary.json").read_text())
    assert on_disk["status"] == "interrupted"
    assert (tmp_path / "checkpoint.bin").is_file()


# --- sweeps ------------------------------------------------------------------

GRID = {"speed": ["6000 rpm", "9000 rpm"], "axial": ["150 N", "300 N"]}


def rows_without_wall(result):
    return [{k: v for k, v in r.items() if k != "wall_time_s"} for r in result]


def test_sweep_rows_equal_the_clis_run_sweep(tmp_path):
    cli("run", "--duration", "1 ms", "--sweep", "speed=6000rpm,9000rpm",
        "--sweep", "axial=150N,300N", "-o", str(tmp_path / "cli"))
    expected = json.loads((tmp_path / "cli" / "sweep.json").read_text())
    result = rolldyn.sweep(None, GRID, duration="1 ms", output=tmp_path / "py")
    assert len(result) == 4
    assert [r["speed"] for r in result] == ["6000 rpm", "6000 rpm", "9000 rpm", "9000 rpm"]
    assert all(r["status"] == "completed" for r in result)
    for row, cli_row in zip(rows_without_wall(result), expected):
        cli_row.pop("wall_time_s")
        assert {k: v for k, v in row.items() if k not in GRID} == cli_row
    assert (tmp_path / "py" / "sweep.json").is_file()
    assert (tmp_path / "py" / "point-0003" / "timeseries.parquet").is_dir()
    assert result.column("mean_cage_speed_rpm").shape == (4,)
    # The labelled dataset: every point's signals, keyed by the rows' point.
    signals = result.signals().to_table(columns=["point", "time_s", "cage_speed_rpm"])
    for row in result:
        point = pq.read_table(tmp_path / "py" / row["point"] / "timeseries.parquet")
        mine = signals.filter(pa.compute.equal(signals["point"], row["point"]))
        assert mine["cage_speed_rpm"].to_pylist() == point["cage_speed_rpm"].to_pylist()
    assert signals.num_rows == sum(
        pq.read_table(tmp_path / "py" / r["point"] / "timeseries.parquet").num_rows for r in result)


def test_sampled_sweep_equals_the_clis(tmp_path):
    """``sample=N, seed=S`` draws the same points as ``--sample N --seed S``."""
    cli("run", "--duration", "1 ms", "--sweep", "cage.pocket_friction=0.05..0.1",
        "--sweep", "axial=150N,300N", "--sample", "3", "--seed", "4",
        "-o", str(tmp_path / "cli"))
    expected = json.loads((tmp_path / "cli" / "sweep.json").read_text())
    grid = {"cage.pocket_friction": "0.05..0.1", "axial": ["150N", "300N"]}
    result = rolldyn.sweep(None, grid, duration="1 ms", sample=3, seed=4)
    assert len(result) == 3
    for row, cli_row in zip(result, expected):
        assert row["cage.pocket_friction"] == cli_row["cage.pocket_friction"]
        assert row["axial"] == cli_row["operating.force_x"]
        assert row["mean_cage_speed_rpm"] == cli_row["mean_cage_speed_rpm"]


def test_sweep_on_a_dask_local_cluster_equals_the_serial_sweep(tmp_path):
    distributed = pytest.importorskip("distributed")
    serial = rolldyn.sweep(None, GRID, duration="1 ms")
    # An earlier, larger sweep's point (a run directory) goes; a folder
    # that is not a run stays.
    (tmp_path / "point-0007").mkdir()
    (tmp_path / "point-0007" / "run.json").write_text("{}")
    (tmp_path / "point-0008").mkdir()
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        seen = []
        on_dask = rolldyn.sweep(None, GRID, client, duration="1 ms",
                                output=tmp_path, progress=seen.append)
    assert rows_without_wall(on_dask) == rows_without_wall(serial)
    assert seen[-1] == pytest.approx(1.0)
    assert json.loads((tmp_path / "sweep.json").read_text())[0]["point"] == "point-0000"
    assert (tmp_path / "point-0002" / "summary.json").is_file()
    assert not (tmp_path / "point-0007").exists()
    assert (tmp_path / "point-0008").is_dir()

    # A Ctrl-C (here raised by the progress callback after the first point)
    # keeps the finished points and marks the rest.
    def interrupt(fraction):
        raise KeyboardInterrupt

    with distributed.LocalCluster(n_workers=1, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        with pytest.raises(rolldyn.RunInterrupted) as e:
            rolldyn.sweep(None, GRID, client, duration="5 ms", progress=interrupt)
    partial = e.value.result
    assert len(partial) == 4
    statuses = [r["status"] for r in partial]
    assert "completed" in statuses and "not_started" in statuses
    assert set(statuses) <= {"completed", "not_started"}


def test_sweep_refuses_a_bad_point_before_running():
    with pytest.raises(rolldyn.CaseError, match="operating.speed"):
        rolldyn.sweep(None, {"speed": ["1000 rpm", "very fast"]}, duration="1 ms")
    with pytest.raises(rolldyn.CaseError, match="list of values"):
        rolldyn.sweep(None, {"speed": "1000 rpm"})


# --- the other commands: power, thermal, traction, spectrum -----------------------

SEED004 = REPO / "examples" / "seed004" / "case.toml"


def test_power_and_thermal_equal_the_cli():
    case = rolldyn.Case.load(SEED004)
    assert rolldyn.power(case) == cli_json("power", str(SEED004), "--json")
    expected = cli_json("thermal", str(SEED004), "--json", "--transient", "10 min",
                        "--steps", "40")
    assert rolldyn.thermal(case, transient="10 min", steps=40) == expected
    with pytest.raises(rolldyn.CaseError, match="--transient"):
        rolldyn.thermal(case, transient="-1 s")


def test_run_of_a_bearing_set(tmp_path):
    pair = REPO / "examples" / "spindle_pair" / "case.toml"
    case = rolldyn.Case.load(pair).set("output.sample_rate", "5 kHz")
    result = rolldyn.run(case, "2 ms", output=tmp_path / "pair")
    assert result.summary["kind"] == "back_to_back"
    assert result.summary["status"] == "completed"
    assert len(result.summary["bearings"]) == 2
    assert result["bearing1_axial_load_n"].unit == "N"
    assert len(result["shaft_x_m"]) == 11


def test_a_drive_torque_and_its_inertia_are_set_together(tmp_path):
    case = rolldyn.Case.preset("7008C")
    with pytest.raises(rolldyn.CaseError, match="operating.rotor_inertia"):
        case.set("operating.drive_torque", "0 N.m")
    run_down = case.with_values(
        {"operating.drive_torque": "0 N.m", "operating.rotor_inertia": "1e-4 kg.m^2"}
    )
    result = rolldyn.run(run_down, "2 ms", output=tmp_path / "run_down")
    speed = result["inner_ring_speed_rpm"]
    assert speed[0] == 10000.0
    assert speed[-1] < speed[0]
    assert result.summary["final_inner_ring_speed_rpm"] == speed[-1]


def test_thermal_of_a_bearing_set_equals_the_cli():
    pair = REPO / "examples" / "spindle_pair" / "case.toml"
    got = rolldyn.thermal(rolldyn.Case.load(pair))
    assert got == cli_json("thermal", str(pair), "--json")
    assert got["operating_preload_at_speed_n"] > got["reference_preload_at_speed_n"]
    assert len(got["bearings"]) == 2


def test_traction_equals_the_cli(tmp_path):
    law = '{ law = "fastsim", friction = 0.1 }'
    case = rolldyn.Case.default().set("model.traction", law)
    flags = dict(load="500 N", rolling_speed="10 m/s", creepages="1e-3,0,5")
    got = rolldyn.traction(case, map=tmp_path / "py.csv", **flags)
    expected = cli_json("traction", "--set", f"model.traction={law}", "--json",
                        "--load", "500 N", "--rolling-speed", "10 m/s",
                        "--creepages", "1e-3,0,5", "--map", str(tmp_path / "cli.csv"))
    assert got == expected
    assert (tmp_path / "py.csv").read_text() == (tmp_path / "cli.csv").read_text()
    # The keywords are the CLI's flags: an unknown one is a TypeError.
    with pytest.raises(TypeError, match="no_such_flag"):
        rolldyn.traction(case, no_such_flag=1, **flags)
    # Bad values get the CLI's message.
    with pytest.raises(rolldyn.CaseError, match="--rolling-speed"):
        rolldyn.traction(case, **{**flags, "rolling_speed": "fast"})



def test_traction_exact_method_equals_the_cli():
    """Kalker's exact theory from Python: the flags pass through."""
    law = '{ law = "fastsim", friction = 0.1 }'
    case = rolldyn.Case.default().set("model.traction", law)
    flags = dict(load="500 N", rolling_speed="10 m/s", creepages="1e-3,0,5")
    got = rolldyn.traction(case, method="exact", cells="16", **flags)
    expected = cli_json("traction", "--set", f"model.traction={law}", "--json",
                        "--load", "500 N", "--rolling-speed", "10 m/s",
                        "--creepages", "1e-3,0,5", "--method", "exact", "--cells", "16")
    assert got == expected
    assert got["method"] == "exact" and got["exact"]["converged"]
    assert got["exact"]["cells_along"] == 16

def test_exact_table_law_equals_the_cli():
    """The tabulated exact theory as a case's law, from Python and the CLI."""
    law = '{ law = "exact_table", friction = 0.1 }'
    case = rolldyn.Case.default().set("model.traction", law)
    flags = dict(load="500 N", rolling_speed="10 m/s", creepages="1e-3,0,5")
    got = rolldyn.traction(case, **flags)
    expected = cli_json("traction", "--set", f"model.traction={law}", "--json",
                        "--load", "500 N", "--rolling-speed", "10 m/s",
                        "--creepages", "1e-3,0,5")
    assert got == expected
    assert got["traction_law"] == "exact_table" and got["power_w"] > 0.0


def test_spectrum_equals_the_cli(tmp_path):
    result = rolldyn.run(duration="5 ms", output=tmp_path)
    expected = cli_json("spectrum", str(tmp_path), "--channel", "cage_speed_rpm", "--json")
    assert result.spectrum("cage_speed_rpm") == expected
    with pytest.raises(rolldyn.CaseError, match="no such channel"):
        result.spectrum("nope")
    # A spectrogram (speed ramps): segments of 16 samples, half overlapping.
    expected = cli_json("spectrum", str(tmp_path), "--channel", "cage_speed_rpm",
                        "--kind", "spectrogram", "--segment", "16", "--json")
    got = result.spectrum("cage_speed_rpm", kind="spectrogram", segment=16)
    assert got == expected and got["segments"] >= 1


def test_native_stub_matches_the_module():
    """``_rolldyn.pyi`` declares exactly what the native module exports,
    and the package exports only its API (``__all__``)."""
    import re
    from rolldyn import _rolldyn

    stub = (Path(rolldyn.__file__).parent / "_rolldyn.pyi").read_text()
    declared = set(re.findall(r"^def (\w+)\(", stub, re.M))
    declared |= set(re.findall(r"^class (\w+)\(", stub, re.M))
    declared |= set(re.findall(r"^([A-Z]\w*): ", stub, re.M))
    exported = {n for n in dir(_rolldyn) if not n.startswith("__")}
    assert declared == exported
    assert (Path(rolldyn.__file__).parent / "py.typed").exists()
    assert {"np", "os", "json", "Any"}.isdisjoint(rolldyn.__all__)
    assert all(hasattr(rolldyn, name) for name in rolldyn.__all__)



def test_a_sensor_gives_the_housing_record_as_numpy(tmp_path):
    case = rolldyn.Case.load(REPO / "examples" / "cwru6205" / "case.toml").set("sensor.seed", 3)
    result = rolldyn.run(case, duration="20 ms", output=tmp_path / "py")
    acquired = result["sensor_acceleration_m_s2"]
    assert isinstance(acquired, np.ndarray)
    assert len(acquired) == len(result["time_s"])
    assert np.isfinite(acquired).all()
    assert result.summary["sensor"]["kurtosis"] > 0
    assert result.summary["envelope_lines"]["channel"] == "sensor_acceleration_m_s2"
