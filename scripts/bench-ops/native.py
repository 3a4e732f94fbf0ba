"""Native OpenCV (opencv-python-headless, one thread) on the same files and
with the same timing rules as bench.mjs. Benchmark only (runs from
.venv-bench).
    python native.py DATA_DIR SIZES TASKS   all at once: prints
        {"task@size": {median, min, max, n, cpu_median}} as JSON
    python native.py DATA_DIR --serve       one request per stdin line,
        "TASK SIZE", one JSON line back: bench.mjs asks right after timing
        the same task in Node, so that all three columns see the same load
Wall-clock ms (time.perf_counter) as TASKS.md says, and the process's CPU
ms of the same calls (time.process_time) for loaded machines.
"""
import json
import math
import os
import sys
import time

import cv2
import numpy as np

cv2.setNumThreads(1)
data = sys.argv[1]
serve = sys.argv[2] == "--serve"
env = lambda k, d: float(os.environ.get(k, d))
BUDGET, MINR, MAXR, WARM = env("BENCH_BUDGET_S", 1.5), int(env("BENCH_MIN_REPS", 5)), int(env("BENCH_MAX_REPS", 25)), int(env("BENCH_WARMUP", 2))
manifest = json.load(open(os.path.join(data, "manifest.json")))


def timed(fn):
    last = 0.0
    for _ in range(WARM):
        t0 = time.perf_counter(); fn(); last = time.perf_counter() - t0
    n = min(MAXR, max(MINR, math.floor(BUDGET / max(last, 1e-6))))
    ts, cs = [], []
    for _ in range(n):
        c0 = time.process_time(); t0 = time.perf_counter(); fn()
        ts.append((time.perf_counter() - t0) * 1000); cs.append((time.process_time() - c0) * 1000)
    ts.sort(); cs.sort()
    return {"median": ts[n // 2], "min": ts[0], "max": ts[-1], "n": n, "cpu_median": cs[n // 2]}


def jobs_for(n):
    p = manifest["sizes"][str(n)]
    g = np.fromfile(os.path.join(data, p["gray"]), np.uint8).reshape(n, n)
    b = np.fromfile(os.path.join(data, p["binary"]), np.uint8).reshape(n, n)
    k = np.exp(-np.arange(-2, 3) ** 2 / 2.0); k = (k / k.sum()).astype(np.float32)
    rx, ry, rw, rh = p["t4_region"]; tx, ty, tw, th = p["t4_template"]
    region, templ = g[ry:ry + rh, rx:rx + rw], g[ty:ty + th, tx:tx + tw]
    M = np.array(p["t5_inverse_map"], np.float64)
    R = cv2.BORDER_REPLICATE

    def t3():
        gx = cv2.Sobel(g, cv2.CV_32F, 1, 0, ksize=1, scale=0.5, borderType=R)
        gy = cv2.Sobel(g, cv2.CV_32F, 0, 1, ksize=1, scale=0.5, borderType=R)
        sxx = cv2.boxFilter(gx * gx, -1, (5, 5), normalize=False, borderType=R)
        syy = cv2.boxFilter(gy * gy, -1, (5, 5), normalize=False, borderType=R)
        sxy = cv2.boxFilter(gx * gy, -1, (5, 5), normalize=False, borderType=R)
        det = sxx * syy - sxy * sxy; tr = sxx + syy
        return cv2.divide(det, tr), cv2.divide(4 * det, tr * tr)

    def t4():
        r = cv2.matchTemplate(region, templ, cv2.TM_CCOEFF_NORMED)
        return cv2.minMaxLoc(r)

    def t2():
        gx = cv2.Sobel(g, cv2.CV_32F, 1, 0, ksize=3, borderType=R)
        gy = cv2.Sobel(g, cv2.CV_32F, 0, 1, ksize=3, borderType=R)
        return cv2.magnitude(gx, gy)

    jobs = {
        "T1_mean3": lambda: cv2.boxFilter(g, cv2.CV_32F, (3, 3), normalize=True, borderType=R),
        "T1_gauss5": lambda: cv2.sepFilter2D(g, cv2.CV_32F, k, k, borderType=R),
        "T2_sobel": t2,
        "T3_foerstner": t3,
        "T4_ncc": t4,
        "T5_bilinear": lambda: cv2.warpAffine(g, M, (n, n), flags=cv2.INTER_LINEAR | cv2.WARP_INVERSE_MAP, borderMode=cv2.BORDER_CONSTANT, borderValue=0),
        "T5_bicubic": lambda: cv2.warpAffine(g, M, (n, n), flags=cv2.INTER_CUBIC | cv2.WARP_INVERSE_MAP, borderMode=cv2.BORDER_CONSTANT, borderValue=0),
        "T6_median3": lambda: cv2.medianBlur(g, 3),
        "T7_contours": lambda: cv2.findContours(b, cv2.RETR_LIST, cv2.CHAIN_APPROX_NONE),
    }
    return jobs


if serve:
    cache = {}
    for line in sys.stdin:
        t, n = line.split()
        n = int(n)
        if n not in cache:
            cache.clear(); cache[n] = jobs_for(n)
        job = cache[n].get(t)
        print(json.dumps(timed(job) if job else None), flush=True)
else:
    sizes, tasks = [int(s) for s in sys.argv[2].split(",")], sys.argv[3].split(",")
    out = {}
    for n in sizes:
        jobs = jobs_for(n)
        for t in tasks:
            if t in jobs:
                out[f"{t}@{n}"] = timed(jobs[t])
    print(json.dumps(out))
