#!/usr/bin/env python3
"""The studio left open (issue 35: "the page left open for an hour, memory flat"): a world that
moves all the time, one page open throughout, a second page reloaded every --reload seconds,
and every --sample seconds the memory of each part.

  src/sim_studio_tests/bench/bench_studio_soak.py [--world maze] [--minutes 60] [--sample 60] [--reload 30]

The world is bench_studio_world.py's (its own roslaunch and master), at real time, kept moving
(m_robot turning on the spot; the Katana's arm sweeping). Measured at each sample:
- the studio node's resident memory (VmRSS, its process and children);
- the open page's JavaScript heap after a forced garbage collection (Chrome DevTools'
  HeapProfiler.collectGarbage, then Runtime.getHeapUsage) and its DOM nodes and event listeners
  (Performance.getMetrics);
- the frames it drew since the last sample, and the pages the studio counts (/status.json:
  always 2 if a reloaded page is forgotten).
The first --warmup minutes (caches, the JIT) are left out of the trend: each figure's least
squares slope over the rest, per hour, with its first, last and largest value.
"""
import argparse
import json
import os
import sys
import threading
import time
import urllib.request

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "test", "browser"))
from bench_studio_world import Motion, World, load_average, node_pid  # noqa: E402

COMMAND = "src/sim_studio_tests/bench/bench_studio_soak.py"


def rss_mb(pid):
    with open("/proc/%d/status" % pid) as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) / 1024.0
    return float("nan")


def page_memory(driver):
    driver.execute_cdp_cmd("HeapProfiler.collectGarbage", {})
    heap = driver.execute_cdp_cmd("Runtime.getHeapUsage", {})
    metrics = {m["name"]: m["value"] for m in driver.execute_cdp_cmd("Performance.getMetrics", {})["metrics"]}
    return {"js_heap_mb": heap["usedSize"] / 2 ** 20, "dom_nodes": metrics.get("Nodes"),
            "listeners": metrics.get("JSEventListeners")}


def slope_per_hour(times, values):
    n = len(times)
    if n < 2:
        return float("nan")
    mt, mv = sum(times) / n, sum(values) / n
    var = sum((t - mt) ** 2 for t in times)
    return sum((t - mt) * (v - mv) for t, v in zip(times, values)) / var * 3600.0 if var else float("nan")


class Reloader:
    """A second page, reloaded every `period` seconds, on its own thread."""

    def __init__(self, world, period):
        from studio_browser import open_browser, open_studio
        self.url, self.period, self.stop_flag = world.url(), period, threading.Event()
        self.driver = open_browser()
        open_studio(self.driver, self.url)
        self.reloads, self.failures = 0, []
        self._open = open_studio
        self.thread = threading.Thread(target=self._run, daemon=True)
        self.thread.start()

    def _run(self):
        while not self.stop_flag.wait(self.period):
            try:
                self.driver.refresh()
                self._open(self.driver, self.url)
                self.reloads += 1
            except Exception as e:  # counted and shown: a reload that fails is a finding
                self.failures.append(str(e)[:200])

    def close(self):
        self.stop_flag.set()
        self.thread.join()
        self.driver.quit()


def soak(args):
    world = World(args.world)
    world.set_target(1.0)
    world.open_page()
    world.driver.execute_cdp_cmd("Performance.enable", {})
    studio = node_pid("/sim_studio")
    status_url = world.url().split("?")[0].rstrip("/") + "/status.json"
    reloader = Reloader(world, args.reload)
    samples = []
    start = time.monotonic()
    try:
        with Motion(world):
            last = world.js("window.studio.world.stats()")
            while True:
                elapsed = time.monotonic() - start
                stats = world.js("window.studio.world.stats()")
                with urllib.request.urlopen(status_url, timeout=5) as reply:
                    pages = json.load(reply)["pages"]
                sample = {"minute": elapsed / 60.0, "studio_rss_mb": rss_mb(studio), "pages": pages,
                          "fps": (stats["renders"] - last["renders"]) / max(1e-3, (stats["at"] - last["at"]) / 1000.0),
                          "reloads": reloader.reloads}
                sample.update(page_memory(world.driver))
                samples.append(sample)
                last = stats
                print("  %5.1f min: studio %6.1f MB, page heap %6.2f MB, %5d DOM nodes, %4d listeners, %4.1f frames/s,"
                      " %d pages, %d reloads" % (sample["minute"], sample["studio_rss_mb"], sample["js_heap_mb"],
                                                  sample["dom_nodes"], sample["listeners"], sample["fps"], pages,
                                                  reloader.reloads), flush=True)
                if elapsed >= args.minutes * 60:
                    break
                time.sleep(args.sample)
    finally:
        reloader.close()
        world.close()
    return samples, reloader.failures


def report(samples, failures, args):
    kept = [s for s in samples if s["minute"] >= args.warmup]
    print("\nStudio soak: %s world moving, one page open %.0f min, a second reloaded every %.0f s (%d reloads, %d failed);"
          " load average now %.1f" % (args.world, samples[-1]["minute"], args.reload, samples[-1]["reloads"],
                                      len(failures), load_average()))
    times = [s["minute"] * 60 for s in kept]
    for key, unit in (("studio_rss_mb", "MB"), ("js_heap_mb", "MB"), ("dom_nodes", ""), ("listeners", "")):
        values = [s[key] for s in kept]
        print("  %-14s from %.1f min: first %8.2f, last %8.2f, max %8.2f %s; trend %+.2f %s/hour"
              % (key, args.warmup, values[0], values[-1], max(values), unit, slope_per_hour(times, values), unit))
    print("  frames/s: min %.1f, median %.1f; pages counted: %s" % (
        min(s["fps"] for s in samples[1:]), sorted(s["fps"] for s in samples[1:])[len(samples[1:]) // 2],
        sorted({s["pages"] for s in samples})))
    for f in failures[:5]:
        print("  reload failed: " + f)
    print("\nreproduce: %s %s" % (COMMAND, " ".join(sys.argv[1:])))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--world", default="maze", choices=("maze", "katana"))
    parser.add_argument("--minutes", type=float, default=60.0, help="how long the page stays open")
    parser.add_argument("--sample", type=float, default=60.0, help="seconds between samples")
    parser.add_argument("--reload", type=float, default=30.0, help="seconds between reloads of the second page")
    parser.add_argument("--warmup", type=float, default=5.0, help="minutes left out of the trend")
    args = parser.parse_args()
    samples, failures = soak(args)
    report(samples, failures, args)


if __name__ == "__main__":
    main()
