#!/usr/bin/env python3
"""Opens a run report (report.html) in headless Chromium and checks what a reader would see:

  - the page loads without console errors, and asks for nothing outside itself (no http(s),
    no files beside it: every picture is inlined);
  - every image decodes, at the size the page says it has (data-width, data-height) and > 0;
  - the headline number (span#headline-tonnes or #headline-w, its data-value) equals the run's
    own number in summary.json or calibration.json, and its text shows it in t, kt or Mt;
  - with --expect-warning TEXT: the warnings section shows TEXT.

A checking script is added to a copy of the page (the report itself carries none), Chromium
dumps the page's DOM after load, and the script's findings are read from it.

  check_report.py RUN_DIR [--expect-warning TEXT] [--screenshot PNG]
Exit codes: 0 ok, 1 a check failed, 77 Chromium is not installed (the test is skipped).
"""
import argparse, json, os, re, shutil, subprocess, sys, tempfile

CHECK = r"""
<script>
window.addEventListener('load', () => {
  const out = {images: []};
  for (const img of document.images)
    out.images.push({ok: img.complete && img.naturalWidth > 0, w: img.naturalWidth, h: img.naturalHeight,
                     ew: Number(img.dataset.width), eh: Number(img.dataset.height), alt: img.alt});
  for (const id of ['headline-tonnes', 'headline-w', 'headline-count', 'headline-rms']) {
    const h = document.getElementById(id);
    if (h) { out.headline = {id: id, value: h.dataset.value, text: h.textContent}; break; }
  }
  const w = document.getElementById('warnings');
  out.warnings = w ? w.innerText : null;
  const pre = document.createElement('pre');
  pre.id = 'selfcheck';
  pre.textContent = JSON.stringify(out);
  document.body.appendChild(pre);
});
</script>
"""

FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
         "--disable-background-networking", "--disable-component-update", "--disable-sync",
         "--hide-scrollbars"]


def chromium():
    for name in ("chromium", "chromium-browser", "google-chrome"):
        path = shutil.which(name)
        if path:
            return path
    return None


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("run")
    ap.add_argument("--expect-warning")
    ap.add_argument("--screenshot")
    a = ap.parse_args()
    browser = chromium()
    if not browser:
        print("chromium is not installed (scripts/install-deps.sh installs it): skipped")
        sys.exit(77)
    report = os.path.join(a.run, "report.html")
    html = open(report, encoding="utf-8").read()
    # self-contained: nothing fetched from elsewhere
    outside = re.findall(r'(?:src|href)\s*=\s*"(?!data:|#)([^"]*)"', html)
    if outside:
        fail("the page refers to %s (it must be one file)" % outside[:3])
    if re.search(r"https?://", html.split("<pre>")[0]):
        fail("the page names a web address outside its preformatted text")

    work = tempfile.mkdtemp(prefix="abrade_report_")
    page = os.path.join(work, "report.html")
    with open(page, "w", encoding="utf-8") as f:
        f.write(html.replace("</body>", CHECK + "</body>"))
    profile = os.path.join(work, "profile")
    run = subprocess.run([browser] + FLAGS + ["--user-data-dir=" + profile, "--enable-logging=stderr", "--v=0",
                          "--virtual-time-budget=10000", "--dump-dom", "file://" + page],
                         capture_output=True, text=True, timeout=180)
    console = [l for l in run.stderr.splitlines() if "CONSOLE" in l or "Uncaught" in l]
    errors = [l for l in console if re.search(r"Uncaught|Error|Failed to load", l)]
    if errors:
        fail("console errors:\n  " + "\n  ".join(errors[:5]))
    m = re.search(r'<pre id="selfcheck">(.*?)</pre>', run.stdout, re.S)
    if not m:
        fail("the page did not finish loading (no check result); chromium said:\n" + run.stderr[-2000:])
    found = json.loads(m.group(1).replace("&quot;", '"').replace("&lt;", "<").replace("&gt;", ">").replace("&amp;", "&"))

    images = found["images"]
    if not images:
        fail("no images in the report")
    for img in images:
        if not img["ok"]:
            fail("image '%s' does not decode" % img["alt"])
        if img["w"] != img["ew"] or img["h"] != img["eh"] or img["w"] < 100 or img["h"] < 100:
            fail("image '%s' is %dx%d, the page says %dx%d" % (img["alt"], img["w"], img["h"], img["ew"], img["eh"]))
    print("ok: %d images decode at their sizes (%s)" % (len(images), ", ".join("%dx%d" % (i["w"], i["h"]) for i in images)))

    head = found.get("headline")
    if not head:
        fail("no headline number")
    if head["id"] == "headline-tonnes":
        summary = json.load(open(os.path.join(a.run, "summary.json")))
        life = summary["results"]["lifetime"]
        expected = life.get("predicted_tonnes_to_end_of_life")
        if expected is None:
            if head["value"] != "none":
                fail("headline says %s but summary.json has no predicted life" % head["value"])
        else:
            value = float(head["value"])
            if abs(value - expected) > 1e-9 * abs(expected):
                fail("headline %r differs from summary.json's %r" % (value, expected))
            unit, scale = ("Mt", 1e6) if expected >= 1e6 else ("kt", 1e3) if expected >= 1e3 else ("t", 1)
            shown = "%.3g %s" % (expected / scale, unit)
            if shown not in head["text"]:
                fail("headline text %r does not show %r" % (head["text"], shown))
        print("ok: headline %s = summary.json's predicted_tonnes_to_end_of_life (%r)" % (head["text"], expected))
    elif head["id"] == "headline-w":
        cal = json.load(open(os.path.join(a.run, "calibration.json")))
        expected = cal["runs"][0]["archard_coefficient"]
        if abs(float(head["value"]) - expected) > 1e-9 * abs(expected):
            fail("headline W %s differs from calibration.json's %r" % (head["value"], expected))
        print("ok: headline W = calibration.json's (%r)" % expected)
    elif head["id"] == "headline-rms":
        cmp = json.load(open(os.path.join(a.run, "comparison.json")))
        expected = cmp["registration"]["rms_distance"]
        if abs(float(head["value"]) - expected) > 1e-9 * abs(expected):
            fail("headline RMS %s differs from comparison.json's %r" % (head["value"], expected))
        print("ok: headline RMS distance = comparison.json's (%r)" % expected)
    else:
        print("ok: headline %s" % head["text"])

    if a.expect_warning:
        if not found["warnings"] or a.expect_warning not in found["warnings"]:
            fail("the warnings section does not show %r: %r" % (a.expect_warning, found["warnings"]))
        print("ok: the warnings section shows %r" % a.expect_warning)
    if a.screenshot:
        subprocess.run([browser] + FLAGS + ["--user-data-dir=" + profile + "2", "--window-size=1200,2600",
                        "--screenshot=" + os.path.abspath(a.screenshot), "file://" + os.path.abspath(report)],
                       capture_output=True, text=True, timeout=180)
        print("screenshot: " + a.screenshot)
    shutil.rmtree(work, ignore_errors=True)
    print("ok: %s" % report)


if __name__ == "__main__":
    main()
