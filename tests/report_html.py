#!/usr/bin/env python3
"""report.html in a real browser (README.md, "The comparison page").

usage: report_html.py FLUIDSURF SRC OUT CHROMIUM CHROMEDRIVER

Runs three small compares (three methods on one frame; two methods on a 3-frame
sequence, also as two shards merged; a sweep of one parameter), opens their report.html in headless
Chromium through selenium and checks what the browser shows: the first method
in the image area; a key switches the method and the metrics row highlight
follows; the flip shows the reference's pixels (a screenshot of the canvas
against the reference PNG), the split line the method and the reference on
either side, where it is dragged; zooming to 8x and switching keeps the same pixel
under the cursor; clicking a column sorts the rows; a sweep grid cell picks its variant; the sequence's frame
slider changes the image; no request but file:// in the browser's log, no
error. Then: merge of the shards writes the page one process writes (its
embedded data, timings and provenance aside), `fluidsurf report DIR` rewrites
the same bytes, and a folder that is not a finished study is refused in one
line with exit 2. Screenshots stay in OUT for a person to look at.
"""
import json
import os
import re
import shutil
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from png_water import read_png  # noqa: E402

from selenium import webdriver  # noqa: E402
from selenium.webdriver.chrome.service import Service  # noqa: E402
from selenium.webdriver.common.action_chains import ActionChains  # noqa: E402
from selenium.webdriver.common.actions.wheel_input import ScrollOrigin  # noqa: E402
from selenium.webdriver.common.by import By  # noqa: E402
from selenium.webdriver.common.keys import Keys  # noqa: E402

BIN, SRC, OUT, CHROMIUM, DRIVER = sys.argv[1:6]
fails = 0


def check(ok, what):
    global fails
    print(("ok   " if ok else "FAIL ") + what, flush=True)
    if not ok:
        fails += 1
    return ok


def run(args, **kw):
    return subprocess.run([BIN] + args, capture_output=True, text=True, **kw)


def png(path):
    w, h, nch, rows = read_png(path)
    return w, h, nch, rows


def pixel(img, x, y):
    w, h, nch, rows = img
    p = rows[y][x * nch:(x + 1) * nch]
    return tuple(p[:3]) if nch >= 3 else (p[0],) * 3


def close(a, b, tol=3):
    return all(abs(int(u) - int(v)) <= tol for u, v in zip(a, b))


def canvas_matches(shot, img, scale, step=1):
    """Share of the image's opaque pixels the canvas screenshot shows at scale (pan 0)."""
    w, h = img[0], img[1]
    n = ok = 0
    for y in range(0, h, step):
        for x in range(0, w, step):
            if img[2] == 4 and img[3][y][4 * x + 3] != 255:
                continue
            n += 1
            ok += close(pixel(shot, x * scale + scale // 2, y * scale + scale // 2), pixel(img, x, y))
    return ok / max(n, 1)


def columns_match(shot, img, scale, x0, x1):
    """Share of the opaque pixels of image columns x0..x1-1 the canvas shows at scale (pan 0)."""
    n = ok = 0
    for y in range(img[1]):
        for x in range(x0, x1):
            if img[2] == 4 and img[3][y][4 * x + 3] != 255:
                continue
            n += 1
            ok += close(pixel(shot, x * scale + scale // 2, y * scale + scale // 2), pixel(img, x, y))
    return ok / max(n, 1)


def page_data(path):
    text = open(path, encoding="utf-8").read()
    m = re.search(r'<script id="fs-data" type="application/json">\n(.*?)\n</script>', text, re.S)
    return json.loads(m.group(1)), text[:m.start(1)] + text[m.end(1):]


def study(name, scene, methods, extra=()):
    r = run(["compare", scene, "--methods", methods, "-W", "96", "-H", "64", "--repeat", "1", "-q", "--no-cache",
             "-o", name] + list(extra))
    if not check(r.returncode == 0 and os.path.isfile(name + "/report.html"), "compare %s writes report.html" % name):
        print(r.stderr)
        sys.exit(1)


shutil.rmtree(OUT, ignore_errors=True)
os.makedirs(OUT)
os.chdir(OUT)
with open("still.json", "w") as f:
    f.write('{"particles": {"synthetic": "slab", "size": [12, 4, 12]}, "radius": 0.025}')
with open("seq.json", "w") as f:
    f.write('{"particles": {"synthetic": "slab", "size": [12, 4, 12], "first": 0, "last": 2, "moving": true}, '
            '"radius": 0.025}')
study("still", "still.json", "spheres,aniso_ssf,raycast_pca")
study("seq", "seq.json", "spheres,aniso_ssf", ["--counters"])
study("sweep", "still.json", "spheres", ["--set", "spheres.radius_scale=0.8,1.2"])
# the reference has a thickness of its own, not swept: it is no cell of the grid (issue 53)
study("sweep_ref", "still.json", "reference,spheres", ["--set", "spheres.thickness=on,off"])
os.makedirs("shards")
for k in (1, 2):
    r = run(["compare", "seq.json", "--methods", "spheres,aniso_ssf", "-W", "96", "-H", "64", "--repeat", "1", "-q",
             "--no-cache", "--counters", "--shard", "%d/2" % k, "-o", "shards/%d" % k])
    check(r.returncode == 0, "shard %d/2 runs" % k)
r = run(["merge", "shards/1", "shards/2", "-o", "merged"])
check(r.returncode == 0 and os.path.isfile("merged/report.html"), "merge writes report.html")
check("report.html" in open("still/fluidsurf-outputs.txt").read().split(), "report.html is listed in fluidsurf-outputs.txt")

# merge and one process: the same page (the script and style), the same data but timings and provenance
single, single_page = page_data("seq/report.html")
merged, merged_page = page_data("merged/report.html")
check(single_page == merged_page, "the merged page's HTML, script and style equal the single process's")
check(single["pngs"] == merged["pngs"], "the merged page lists the same images")


def body(csv, drop=()):
    lines = [ln for ln in (csv or "").splitlines() if not ln.startswith("#")]
    if not lines:
        return []
    head = lines[0].split(",")
    keep = [i for i, c in enumerate(head) if c not in drop]
    return [[ln.split(",")[i] for i in keep] for ln in lines]


check(body(single["metrics"], ("frame_ms",)) == body(merged["metrics"], ("frame_ms",)),
      "the merged page's metrics equal the single process's, frame_ms aside")
check(body(single["temporal"]) == body(merged["temporal"]), "the merged page's temporal measures are the same")
check(single["counters"] and body(single["counters"]) == body(merged["counters"]), "the merged page's work counters are the same")
tcols = ("ms_median", "ms_min", "ms_max", "gpu_ms_median", "renderer")
check(body(single["timings"], tcols) == body(merged["timings"], tcols), "the merged page's timings have the same rows")
labels = lambda md: [ln for ln in md.splitlines() if ln.startswith("| `")]  # noqa: E731
check(labels(single["report_md"]) == labels(merged["report_md"]), "the merged page has the same label table")
check(single["metrics"] == open("seq/metrics.csv").read(), "the page embeds metrics.csv as it is")

# fluidsurf report DIR: the same writer, the same bytes; a folder that is not a study is refused
before = open("still/report.html", "rb").read()
os.remove("still/report.html")
r = run(["report", "still"])
check(r.returncode == 0 and open("still/report.html", "rb").read() == before, "fluidsurf report DIR rewrites the page compare wrote")
os.makedirs("notastudy")
shutil.copy("still/timings.csv", "notastudy/")
r = run(["report", "notastudy"])
check(r.returncode == 2 and len(r.stderr.strip().splitlines()) == 1 and not os.path.exists("notastudy/report.html"),
      "a folder without metrics.csv: exit 2, one line, no page (%s)" % r.stderr.strip())
with open("notastudy/metrics.csv", "w") as f:
    f.write("method,variant\nspheres,\n")
r = run(["report", "notastudy"])
check(r.returncode == 2 and "provenance" in r.stderr and not os.path.exists("notastudy/report.html"),
      "a metrics.csv without its provenance line: refused (%s)" % r.stderr.strip())

# ---- the browser ----
opts = webdriver.ChromeOptions()
opts.binary_location = CHROMIUM
for a in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage", "--force-device-scale-factor=1",
          "--force-color-profile=srgb", "--window-size=1400,1000"):
    opts.add_argument(a)
opts.set_capability("goog:loggingPrefs", {"browser": "ALL", "performance": "ALL"})
drv = webdriver.Chrome(service=Service(DRIVER), options=opts)
drv.set_page_load_timeout(60)


def status():
    return drv.find_element(By.ID, "status")


def wait_for(cond, what, timeout=10):
    t0 = time.time()
    while time.time() - t0 < timeout:
        try:
            if cond():
                return True
        except Exception:
            pass
        time.sleep(0.1)
    print("  timed out waiting for " + what)
    return False


def canvas_shot(name):
    # images load asynchronously (a busy machine, e.g. beside the sanitizer build, makes that slow)
    wait_for(lambda: status().get_attribute("data-ready") == "1", "the canvas to show its images (" + name + ")", 30)
    path = os.path.join(OUT, name)
    with open(path, "wb") as f:
        f.write(drv.find_element(By.ID, "canvas").screenshot_as_png)
    return png(path)


def press(key):
    ActionChains(drv).send_keys(key).perform()


def methods_in(page):
    return [b.text.split(" ", 1)[1] for b in drv.find_elements(By.CSS_SELECTOR, "#picker button[data-i]")]


def zoom():
    return int(re.search(r"zoom (\d+)x", status().text).group(1))


try:
    drv.get("file://" + os.path.abspath("still/report.html"))
    wait_for(lambda: "zoom" in status().text, "the viewer")
    drv.save_screenshot(os.path.join(OUT, "page_still.png"))
    names = methods_in(drv)
    check(names == ["spheres", "aniso_ssf", "raycast_pca"], "the picker lists the methods in order (%s)" % names)
    base = zoom()
    shot = canvas_shot("c_first.png")
    first = png("still/spheres.png")
    check(status().get_attribute("data-label") == "spheres" and canvas_matches(shot, first, base) > 0.99,
          "the image area shows the first method's pixels (%.3f match at %dx)" % (canvas_matches(shot, first, base), base))

    def shown_rows():
        return [tr.find_elements(By.TAG_NAME, "td")[0].text for tr in drv.find_elements(By.CSS_SELECTOR, "#metrics-table tr.shown")]

    check(shown_rows() == ["spheres"], "the metrics row of the first method is highlighted")
    press("2")
    check(status().get_attribute("data-label") == "aniso_ssf" and shown_rows() == ["aniso_ssf"],
          "key 2 shows aniso_ssf and its metrics row is highlighted (%s)" % shown_rows())
    shot2 = canvas_shot("c_second.png")
    second = png("still/aniso_ssf.png")
    check(canvas_matches(shot2, second, base) > 0.99, "the canvas shows aniso_ssf's pixels")
    press(Keys.ARROW_RIGHT)
    check(status().get_attribute("data-label") == "raycast_pca" and shown_rows() == ["raycast_pca"], "the right arrow shows the next method")
    press(Keys.ARROW_LEFT)
    press("f")
    shot = canvas_shot("c_flip.png")
    ref = png("still/reference.png")
    m_ref, m_meth = canvas_matches(shot, ref, base), canvas_matches(shot, second, base)
    check(status().get_attribute("data-label") == "reference" and m_ref > 0.99 and m_meth < 0.9,
          "f flips to the reference's pixels (%.3f match; %.3f against the method's)" % (m_ref, m_meth))
    press("f")
    check(status().get_attribute("data-label") == "aniso_ssf", "f again flips back")

    # the split line: the method left of it, the reference right of it; dragged to a quarter
    press("d")
    shot = canvas_shot("c_split.png")
    w2 = first[0] // 2
    left, right = columns_match(shot, second, base, 0, w2 - 1), columns_match(shot, ref, base, w2 + 1, first[0])
    check(left > 0.99 and right > 0.99, "d splits: aniso_ssf left of the line, the reference right of it (%.3f, %.3f)" % (left, right))
    cv = drv.find_element(By.ID, "canvas")
    ActionChains(drv).move_to_element_with_offset(cv, 0, 0).click_and_hold().move_by_offset(-cv.size["width"] // 4, 0).release().perform()
    shot = canvas_shot("c_split_dragged.png")
    w4 = first[0] // 4
    left, right = columns_match(shot, second, base, 0, w4 - 1), columns_match(shot, ref, base, w4 + 1, first[0])
    check(left > 0.99 and right > 0.99, "dragging the line to a quarter moves it there (%.3f, %.3f)" % (left, right))
    press("d")

    # zoom at a point to 8x; the pixel under the cursor stays when the method changes
    cv = drv.find_element(By.ID, "canvas")
    dx, dy = 37, -21  # from the canvas' centre
    ActionChains(drv).move_to_element_with_offset(cv, dx, dy).perform()
    for _ in range(8):
        if zoom() >= 8:
            break
        ActionChains(drv).scroll_from_origin(ScrollOrigin.from_element(cv, dx, dy), 0, -120).perform()
        time.sleep(0.2)
    st = status().text
    m = re.search(r"pixel (\d+),(\d+)", st)
    check(zoom() == 8 and m is not None, "the wheel zooms to 8x at the cursor (%s)" % st)
    px, py = int(m.group(1)), int(m.group(2))
    cx, cy = cv.size["width"] // 2 + dx, cv.size["height"] // 2 + dy
    shot = canvas_shot("c_zoom_aniso.png")
    check(close(pixel(shot, cx, cy), pixel(second, px, py)), "at 8x the cursor is on aniso_ssf's pixel %d,%d" % (px, py))
    press("1")
    st2 = status().text
    shot = canvas_shot("c_zoom_spheres.png")
    m2 = re.search(r"pixel (\d+),(\d+)", st2)
    check(m2 is not None and (int(m2.group(1)), int(m2.group(2))) == (px, py) and zoom() == 8,
          "switching to spheres keeps the zoom and the pixel under the cursor (%s)" % st2)
    # the 8x8 block of that pixel shows spheres' colour (and it differs from aniso_ssf's there or nearby)
    check(close(pixel(shot, cx, cy), pixel(first, px, py)) and not close(pixel(first, px, py), pixel(second, px, py)),
          "the cursor is on spheres' pixel %d,%d, whose colour differs from aniso_ssf's" % (px, py))
    check(zoom() == 8 and canvas_matches(shot, first, base) < 0.9, "the canvas is zoomed in, not the whole image")
    press("r")

    # sorting: a numeric column ascending, then descending
    def column(col):
        i = [th.get_attribute("data-col") for th in drv.find_elements(By.CSS_SELECTOR, "#metrics-table th")].index(col)
        return [tr.find_elements(By.TAG_NAME, "td")[i].text for tr in drv.find_elements(By.CSS_SELECTOR, "#metrics-table tbody tr")]

    before = column("method")
    drv.find_element(By.CSS_SELECTOR, '#metrics-table th[data-col="normal_mean_deg"]').click()
    vals = [float(v) for v in column("normal_mean_deg")]
    asc = column("method")
    check(vals == sorted(vals) and len(vals) == 3, "clicking normal_mean_deg sorts the rows ascending (%s)" % vals)
    drv.find_element(By.CSS_SELECTOR, '#metrics-table th[data-col="normal_mean_deg"]').click()
    vals = [float(v) for v in column("normal_mean_deg")]
    check(vals == sorted(vals, reverse=True) and column("method") == asc[::-1] and (asc != before or column("method") != before),
          "a second click reverses them (%s)" % column("method"))
    check(shown_rows() == ["spheres"], "the highlight stays on the shown method's row after sorting")
    csv_rows = [ln.split(",") for ln in open("still/metrics.csv").read().splitlines() if not ln.startswith("#")]
    check(sorted(column("normal_mean_deg")) == sorted(r[csv_rows[0].index("normal_mean_deg")] for r in csv_rows[1:]),
          "the table shows metrics.csv's own numbers")
    bars = drv.find_elements(By.CSS_SELECTOR, "#timings-svg rect[data-stage]")
    tips = [b.find_element(By.TAG_NAME, "title").get_attribute("textContent") for b in bars]
    check(len(bars) > 3 and all(" on " in t and ": " in t for t in tips), "timings are stacked SVG bars with the stage and renderer (%s)" % tips[:1])
    fills = {}
    for b in bars:
        fills.setdefault(b.get_attribute("data-stage"), set()).add(b.get_attribute("fill"))
    check(all(len(f) == 1 for f in fills.values()) and len(set.union(*fills.values())) == len(fills),
          "each of the %d stages has one colour, none shared (%s)" % (len(fills), sorted(fills)))
    press("l")
    shot = canvas_shot("c_heat_normal.png")
    heat = png("still/heat_normal_spheres.png")
    check(canvas_matches(shot, heat, base) > 0.99, "layer l shows the normal-error heatmap's pixels")
    press("l")
    press("l")
    drv.save_screenshot(os.path.join(OUT, "page_still_after.png"))

    # a sweep: the grid's cells pick the variant
    drv.get("file://" + os.path.abspath("sweep/report.html"))
    wait_for(lambda: "zoom" in status().text, "the sweep's viewer")
    cells = drv.find_elements(By.CSS_SELECTOR, "#grid td[data-i]")
    check(len(cells) == 2, "the sweep grid has a cell per variant (%d)" % len(cells))
    cells[1].click()
    shot = canvas_shot("c_sweep.png")
    big = png("sweep/spheres_radius_scale-1p2.png")
    check(status().get_attribute("data-label") == "spheres_radius_scale-1p2" and canvas_matches(shot, big, zoom()) > 0.99 and
          canvas_matches(shot, png("sweep/spheres_radius_scale-0p8.png"), zoom()) < 0.95,
          "clicking the grid's second cell shows radius_scale 1.2 (%s)" % status().get_attribute("data-label"))
    drv.save_screenshot(os.path.join(OUT, "page_sweep.png"))
    drv.get("file://" + os.path.abspath("sweep_ref/report.html"))
    wait_for(lambda: "zoom" in status().text, "the second sweep's viewer")
    titles = [c.get_attribute("title") for c in drv.find_elements(By.CSS_SELECTOR, "#grid td[data-i]")]
    check(titles == ["spheres_thickness-on", "spheres_thickness-off"],
          "the sweep grid holds the swept method's variants only, not the reference (%s)" % titles)

    # a folder with the numbers only (an older study's committed summary): the tables, no viewer, no error
    os.makedirs("numbers_only")
    for f in ("metrics.csv", "timings.csv", "report.md"):
        shutil.copy("still/" + f, "numbers_only/")
    r = run(["report", "numbers_only"])
    drv.get("file://" + os.path.abspath("numbers_only/report.html"))
    wait_for(lambda: drv.find_elements(By.ID, "noimages"), "the numbers-only page")
    check(r.returncode == 0 and len(drv.find_elements(By.CSS_SELECTOR, "#metrics-table tbody tr")) == 3 and
          drv.find_elements(By.ID, "noimages"), "a folder without PNGs gets the tables and a note in place of the viewer")

    # the sequence: the slider changes the frame and the image
    drv.get("file://" + os.path.abspath("seq/report.html"))
    wait_for(lambda: "zoom" in status().text, "the sequence's viewer")
    base = zoom()
    f0 = canvas_shot("c_seq_f0.png")
    check("frame 0" in status().text and canvas_matches(f0, png("seq/spheres_f0000.png"), base) > 0.99, "the sequence opens on frame 0")
    slider = drv.find_element(By.ID, "frame")
    slider.click()
    slider.send_keys(Keys.HOME)
    slider.send_keys(Keys.ARROW_RIGHT)
    f1 = canvas_shot("c_seq_f1.png")
    m1 = canvas_matches(f1, png("seq/spheres_f0001.png"), base)
    check("frame 1" in status().text and m1 > 0.99 and canvas_matches(f1, png("seq/spheres_f0000.png"), base) < 0.95,
          "the slider moves to frame 1 and the image changes to it (%.3f)" % m1)
    rows = drv.find_elements(By.CSS_SELECTOR, "#metrics-table tr.shown.frame")
    check(len(rows) == 1 and rows[0].get_attribute("data-frame") == "1", "the metrics row of the shown frame is marked")
    press(" ")
    played = wait_for(lambda: "frame 2" in status().text, "play to reach frame 2", 5)
    press(" ")
    check(played and drv.find_element(By.ID, "play").text == "play", "space plays the sequence and pauses it again")
    slider.send_keys(Keys.HOME)
    slider.send_keys(Keys.ARROW_RIGHT)
    check(len(drv.find_elements(By.CSS_SELECTOR, "#temporal-table tbody tr")) == 2, "the temporal table is beside it")
    ncount = len([ln for ln in open("seq/counters.csv").read().splitlines() if not ln.startswith("#")]) - 1
    check(len(drv.find_elements(By.CSS_SELECTOR, "#counters-table tbody tr")) == ncount > 0, "the work counters' table has counters.csv's %d rows" % ncount)
    commit = re.search(r"commit=([0-9a-f]+)", open("seq/metrics.csv").readline()).group(1)
    prov = [li.text for li in drv.find_elements(By.CSS_SELECTOR, "#prov li")]
    check("commit=" + commit in prov and any(t.startswith("gl_renderer=") for t in prov), "the provenance names the commit and the renderer")
    drv.save_screenshot(os.path.join(OUT, "page_seq.png"))

    # no request but the folder's own files, no error
    urls = []
    for e in drv.get_log("performance"):
        msg = json.loads(e["message"])["message"]
        if msg.get("method") == "Network.requestWillBeSent":
            urls.append(msg["params"]["request"]["url"])
    off = [u for u in urls if not u.startswith("file://")]
    check(len(urls) >= 4 and not off, "%d requests, all file:// (%s)" % (len(urls), off[:3]))
    errors = [e for e in drv.get_log("browser") if e["level"] == "SEVERE"]
    check(not errors, "no error in the browser's console (%s)" % errors[:2])
finally:
    drv.quit()
print("%d failure(s)" % fails)
sys.exit(1 if fails else 0)
