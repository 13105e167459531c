#!/usr/bin/env python3
"""What any page drawing 30 frames a second costs the simulator, against the studio's (issue 35):
the floor under bench_studio_world.py's moving-world slow-down, in Debian's headless Chromium.

  src/sim_studio_tests/bench/bench_studio_floor.py [--worlds katana,maze] [--rounds 8] [--rtf-seconds 4]

The world moves all the time (bench_studio_world.Motion), the simulator unthrottled. Each round
measures its real-time factor over --rtf-seconds with the browser on each of these, in turn:

  none    about:blank
  2d      a window-sized 2D canvas filled with a new colour 30 times a second: the cheapest
          page that changes every frame
  webgl   a window-sized WebGL canvas cleared 30 times a second, at the studio's settings on a
          CPU renderer (3/4 of a pixel per CSS pixel, no antialiasing): the cheapest WebGL page
  studio  the studio's World view drawing the moving world (30 frames a second on a CPU renderer)

A page window's slow-down is 1 - its RTF / the mean of the round's `none` and the next one's;
the median and quartiles over the rounds, with the cores the browser used meanwhile. The bare
pages show how much of the studio's cost is Chromium's own; on a noisy machine the cores a frame
costs are the steadier figure (docs/PERFORMANCE.md).
"""
import argparse
import base64
import json
import os
import statistics
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "test", "browser"))
from bench_studio_world import Motion, World, load_average, measure_in_children, percentile  # noqa: E402

COMMAND = "src/sim_studio_tests/bench/bench_studio_floor.py"
PAGES = ("2d", "webgl", "studio")

# window.frames counts what was drawn, so that a page that fell behind shows it.
BARE_PAGE = """<!doctype html><html><body style="margin:0;overflow:hidden"><canvas id="c"></canvas><script>
const canvas = document.getElementById("c"), scale = %(scale)s;
canvas.width = Math.round(innerWidth * scale); canvas.height = Math.round(innerHeight * scale);
canvas.style.width = innerWidth + "px"; canvas.style.height = innerHeight + "px";
%(setup)s
window.drawn = 0; let last = 0;
function frame(t) {
  requestAnimationFrame(frame);
  if (t - last < 1000 / 30 - 1) return;
  last = t; const shade = (window.drawn %% 64) / 64;
  %(draw)s
  window.drawn++;
}
requestAnimationFrame(frame);
</script></body></html>"""
BARE = {
    "2d": {"scale": "1", "setup": "const g = canvas.getContext('2d', {alpha: false});",
           "draw": "g.fillStyle = 'rgb(' + Math.round(255 * shade) + ',120,120)';"
                   " g.fillRect(0, 0, canvas.width, canvas.height);"},
    "webgl": {"scale": "0.75",
              "setup": "const g = canvas.getContext('webgl', {antialias: false, alpha: false, stencil: false});",
              "draw": "g.clearColor(shade, 0.5, 0.5, 1); g.clear(g.COLOR_BUFFER_BIT | g.DEPTH_BUFFER_BIT);"},
}


def bare_url(kind):
    return "data:text/html;base64," + base64.b64encode((BARE_PAGE % BARE[kind]).encode()).decode()


def drawn(world, page):
    """Frames the page has drawn so far (the studio's own counter, or the bare page's)."""
    return world.js("window.studio.world.stats().renders" if page == "studio" else "window.drawn")


def show(world, page):
    from studio_browser import open_studio, wait_for
    if page == "none":
        world.driver.get("about:blank")
    elif page == "studio":
        open_studio(world.driver, world.url())
        wait_for(world.driver, "return window.studio.world.visualObjects() > 0", 30.0, "the world drawn")
    else:
        world.driver.get(bare_url(page))
    time.sleep(2.0)


def measure(name, rounds, seconds):
    world = World(name)
    result = {"world": name, "load_before": load_average(), "rtf": {}, "cores": {}, "fps": {}}
    try:
        world.set_target(0.0)
        world.open_page()
        with Motion(world):
            time.sleep(1.0)
            for _ in range(rounds + 1):
                for page in ("none",) + PAGES:
                    show(world, page)
                    cpu, start, t0 = {}, None if page == "none" else drawn(world, page), time.monotonic()
                    result["rtf"].setdefault(page, []).append(world.rtf(seconds, cpu))
                    result["cores"].setdefault(page, []).append(cpu["browser"][0])
                    if page != "none":
                        frames = drawn(world, page) - start
                        result["fps"].setdefault(page, []).append(frames / (time.monotonic() - t0))
                    if len(result["rtf"]["none"]) > rounds:
                        break  # the last round is its `none` window only
    finally:
        world.close()
    result["load_after"] = load_average()
    return result


def report(results, argv):
    print("\nAny page's cost, the world moving, headless Chromium (SwiftShader), %d cores, %s"
          % (os.cpu_count(), time.strftime("%Y-%m-%d")))
    for r in results:
        none = r["rtf"]["none"]
        print("\n%s  (load average %.1f before, %.1f after)" % (r["world"], r["load_before"], r["load_after"]))
        print("  unthrottled RTF, no page: %s" % ", ".join("%.1f" % v for v in none))
        for page in PAGES:
            ratios = [v / ((none[i] + none[i + 1]) / 2) for i, v in enumerate(r["rtf"][page])]
            print("  %-6s  frames/s %4.1f  browser %.3f cores (%.1f ms a frame)  slow-down median %5.1f %% "
                  "(quartiles %.1f, %.1f %%)" % (
                      page, statistics.median(r["fps"][page]), statistics.median(r["cores"][page]),
                      1000 * statistics.median(r["cores"][page]) / statistics.median(r["fps"][page]),
                      100 * (1 - statistics.median(ratios)), 100 * (1 - percentile(ratios, 0.75)),
                      100 * (1 - percentile(ratios, 0.25))))
    print("\ntarget: <= 5 %% slow-down with one page\nreproduce: %s %s" % (COMMAND, " ".join(argv)))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--worlds", default="katana,maze", help="comma-separated: katana, maze")
    parser.add_argument("--rounds", type=int, default=8, help="rounds of none, 2d, webgl, studio")
    parser.add_argument("--rtf-seconds", type=float, default=4.0, help="each window (wall s)")
    parser.add_argument("--one", help=argparse.SUPPRESS)  # the child's job: measure this world
    args = parser.parse_args()
    if args.one:
        print("RESULT " + json.dumps(measure(args.one, args.rounds, args.rtf_seconds)), flush=True)
        return
    results = measure_in_children(os.path.abspath(__file__), args.worlds,
                                  ["--rounds", str(args.rounds), "--rtf-seconds", str(args.rtf_seconds)])
    report(results, sys.argv[1:])


if __name__ == "__main__":
    main()
