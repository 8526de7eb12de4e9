#!/usr/bin/env python3
"""Reference statistics of the measured CWRU drive-end records, 0 hp, 1797 rpm.

What: for each record of the Case Western Reserve University Bearing Data
Center used to check a simulated housing accelerometer (SKF 6205-2RS at the
drive end), read the drive-end accelerometer signal XNNN_DE_time (in g) and
the speed XNNNRPM from NNN.mat and write one CSV row with

  rms, peak |a|, crest = peak/rms, kurtosis = m4/m2^2 (Pearson, Gaussian = 3)
      of a = 9.80665 * (DE - mean(DE))                               [m/s^2]
  vel_rms_10_1000: A = rfft(a); V = A / (j 2 pi f) for 10 <= f <= 1000 Hz,
      0 elsewhere; rms = sqrt(2 sum |V_k|^2) / N (Parseval)           [mm/s]
  env: envelope spectrum over the whole record: 4th-order Butterworth band
      pass 1200-4800 Hz (zero phase), |hilbert|, mean removed, Hann window,
      line amplitude 2|X_k| / sum(w); its five largest local maxima in
      5-500 Hz, as "freq:amplitude:line(offset Hz)" joined by ";"; a "?"
      after the line marks an offset above max(1 Hz, 1.5 %). Each is named
      after the nearest characteristic line ("k*" = k-th harmonic): k f_r,
      k FTF, k BPFO, k BPFI, k 2BSF (k = 1..5) and k BPFI +- f_r / FTF,
      k 2BSF +- f_r / FTF sidebands, for the SKF 6205 geometry
      (Z = 9, d = 0.3126 in, D = 1.537 in, alpha = 0) and f_r = rpm / 60:
        FTF  = f_r/2 (1 - d/D)          BPFO = Z FTF
        BPFI = Z (f_r - FTF)            BSF  = D/(2d) f_r (1 - (d/D)^2)

Sampling: the 12k drive-end fault records are at 12 kHz. The normal baseline
97.mat is at 48 kHz (its 243 938 samples span 5.1 s and its shaft line is
at 29.9 Hz only at 48 kHz); it is decimated by 4 (scipy.signal.decimate,
zero phase) to 12 kHz before everything else, so all rows share one bandwidth.

Files: CWRU Bearing Data Center (engineering.case.edu/bearingdatacenter),
"12k Drive End Bearing Fault Data" and "Normal Baseline Data", 0 hp. The
rows in docs/data/cwru_records.csv were made from the mirror named in that
file's first line, copied to NNN.mat. Needs numpy and scipy.

    python3 scripts/cwru_records.py /tmp/cwru docs/data/cwru_records.csv \
        --source "owner/name@commit"
"""
import argparse
import csv
import pathlib

import numpy as np
from scipy.io import loadmat
from scipy.signal import butter, decimate, find_peaks, hilbert, sosfiltfilt

G = 9.80665
FS = 12000.0
RECORDS = {  # record: (fault, diameter [in]), 12k drive end, 0 hp
    97: ("normal", 0.0),
    130: ("outer", 0.007), 105: ("inner", 0.007), 118: ("ball", 0.007),
    197: ("outer", 0.014), 169: ("inner", 0.014), 185: ("ball", 0.014),
    234: ("outer", 0.021), 209: ("inner", 0.021), 222: ("ball", 0.021),
}
FS_FILE = {97: 48000.0}  # records not sampled at 12 kHz
Z, D_BALL, D_PITCH = 9, 0.3126, 1.537


def lines(fr):
    """Characteristic lines {name: frequency [Hz]} of the 6205 at f_r."""
    g = D_BALL / D_PITCH
    ftf = fr / 2 * (1 - g)
    bpfo, bpfi = Z * ftf, Z * (fr - ftf)
    bsf2 = 2 * (D_PITCH / (2 * D_BALL)) * fr * (1 - g * g)
    out = {}
    for k in range(1, 6):
        p = "" if k == 1 else f"{k}*"
        for name, f in (("fr", fr), ("FTF", ftf), ("BPFO", bpfo),
                        ("BPFI", bpfi), ("2BSF", bsf2)):
            out[p + name] = k * f
        for name, f in (("BPFI", bpfi), ("2BSF", bsf2)):
            for sname, s in (("fr", fr), ("FTF", ftf)):
                out[f"{p}{name}+{sname}"] = k * f + s
                out[f"{p}{name}-{sname}"] = k * f - s
    return out


def envelope_lines(a, fs, fr, n=5):
    sos = butter(4, [1200, 4800], btype="bandpass", fs=fs, output="sos")
    env = np.abs(hilbert(sosfiltfilt(sos, a)))
    w = np.hanning(len(env))
    amp = 2 * np.abs(np.fft.rfft((env - env.mean()) * w)) / w.sum()
    f = np.fft.rfftfreq(len(env), 1 / fs)
    sel = (f >= 5) & (f <= 500)
    pk, _ = find_peaks(amp[sel], distance=max(1, int(1.0 / (f[1] - f[0]))))
    pk = pk[np.argsort(amp[sel][pk])[::-1][:n]]
    names = lines(fr)
    out = []
    for fk, ak in zip(f[sel][pk], amp[sel][pk]):
        name = min(names, key=lambda k: abs(names[k] - fk))
        off = fk - names[name]
        flag = "?" if abs(off) > max(1.0, 0.015 * fk) else ""  # far from any
        out.append(f"{fk:.1f}:{ak:.3f}:{name}{flag}({off:+.1f})")
    return ";".join(out)


def record_row(path, rec):
    m = loadmat(path)
    de = [k for k in m if k.endswith("_DE_time")]
    rpm = [k for k in m if k.endswith("RPM")]
    x = np.asarray(m[de[0]], float).ravel()
    rpm_v = float(np.ravel(m[rpm[0]])[0]) if rpm else float("nan")
    if FS_FILE.get(rec, FS) != FS:
        x = decimate(x, int(FS_FILE[rec] / FS), ftype="fir", zero_phase=True)
    a = G * (x - x.mean())
    rms = np.sqrt(np.mean(a * a))
    peak = np.max(np.abs(a))
    kurt = np.mean(a**4) / np.mean(a * a) ** 2
    n = len(a)
    f = np.fft.rfftfreq(n, 1 / FS)
    band = (f >= 10) & (f <= 1000)
    v = np.fft.rfft(a)[band] / (2j * np.pi * f[band])
    vel = 1e3 * np.sqrt(2 * np.sum(np.abs(v) ** 2)) / n
    fault, dia = RECORDS[rec]
    return {
        "record": rec, "fault": fault, "diameter_in": dia,
        "de_var": de[0], "rpm_var": rpm[0] if rpm else "", "rpm": rpm_v,
        "fs_file_hz": FS_FILE.get(rec, FS), "seconds": round(n / FS, 2),
        "rms_ms2": round(rms, 4), "peak_ms2": round(peak, 3),
        "crest": round(peak / rms, 3), "kurtosis": round(kurt, 3),
        "vel_rms_10_1000_mms": round(vel, 4),
        "env_top5_hz_ms2_line": envelope_lines(a, FS, rpm_v / 60),
    }


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("mat_dir", type=pathlib.Path)
    ap.add_argument("out_csv", type=pathlib.Path)
    ap.add_argument("--source", default="",
                    help="owner/name@commit the files came from")
    args = ap.parse_args()
    rows = []
    for rec in RECORDS:
        path = args.mat_dir / f"{rec}.mat"
        if not path.exists():
            print(f"missing: {path}")
            continue
        rows.append(record_row(path, rec))
    args.out_csv.parent.mkdir(parents=True, exist_ok=True)
    with open(args.out_csv, "w", newline="") as fh:
        if args.source:
            fh.write("# CWRU Bearing Data Center records, from github.com/"
                     f"{args.source} (made by scripts/cwru_records.py)\n")
        w = csv.DictWriter(fh, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    for r in rows:
        print(*r.values(), sep=", ")


if __name__ == "__main__":
    main()
