#!/usr/bin/env python3
"""Opens a run report (report.html) in headless Chromium and checks what a reader would see:

  - the page loads without console errors, and asks for nothing outside itself (no http(s),
    no files beside it: every picture is inlined);
  - every image is inlined (data: URI), decodes at the size the page says it has (data-width,
    data-height) and is not blank (its pixels vary); the figures a report of its kind must
    have are there (--expect-figures: trajectory, part, profile for a lifetime run);
  - the browser loaded nothing but the page (no resource requests);
  - the headline number (span#headline-tonnes, #headline-w, #headline-scale or #headline-rms, its data-value)
    equals the run's own number in summary.json, calibration.json or comparison.json, and the
    text shows the same number: for tonnes, the number and unit (t, kt, Mt) read back from the
    text lie within the rounding of three digits of summary.json's value;
  - with --expect-warning TEXT: the warnings section shows TEXT;
  - with --expect-face-table (a part's preview): the face table's rows are summary.json's
    faces (id, role, area), in order.

A checking script is added to a copy of the page (the report itself carries none), Chromium
dumps the page's DOM after load, and the script's findings are read from it.

  check_report.py RUN_DIR [--expect-warning TEXT] [--expect-figures a,b,...] [--expect-face-table] [--screenshot PNG]
Exit codes: 0 ok, 1 a check failed, 77 Chromium is not installed (the test is skipped).
"""
import argparse, json, os, re, shutil, subprocess, sys, tempfile

CHECK = r"""
<script>
window.addEventListener('load', () => {
  const out = {images: [], resources: performance.getEntriesByType('resource').map(e => e.name)};
  for (const img of document.images) {
    let spread = -1;
    try { // the pixels' spread over a grid of samples: 0 for a blank picture
      const c = document.createElement('canvas');
      c.width = img.naturalWidth, c.height = img.naturalHeight;
      const g = c.getContext('2d');
      g.drawImage(img, 0, 0);
      const d = g.getImageData(0, 0, c.width, c.height).data;
      let lo = 255, hi = 0;
      for (let k = 0; k < d.length; k += 4 * 97) { const v = d[k] + d[k + 1] + d[k + 2]; lo = Math.min(lo, v); hi = Math.max(hi, v); }
      spread = hi - lo;
    } catch (e) { spread = -2; }
    out.images.push({ok: img.complete && img.naturalWidth > 0, w: img.naturalWidth, h: img.naturalHeight,
                     ew: Number(img.dataset.width), eh: Number(img.dataset.height), alt: img.alt,
                     inline: img.currentSrc.startsWith('data:image/png;base64,'), spread: spread,
                     figure: img.parentElement.dataset.figure || ''});
  }
  for (const id of ['headline-tonnes', 'headline-w', 'headline-count', 'headline-rms', 'headline-scale', 'headline-volume']) {
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
    ap.add_argument("--expect-figures", default="")
    ap.add_argument("--expect-face-table", action="store_true")
    ap.add_argument("--screenshot")
    a = ap.parse_args()
    browser = chromium()
    if not browser:
        print("chromium is not installed (scripts/install-deps.sh installs it): skipped")
        sys.exit(77)
    report = os.path.join(a.run, "report.html")
    html = open(report, encoding="utf-8", errors="replace").read()
    # self-contained: nothing fetched from elsewhere
    outside = re.findall(r'(?:src|href)\s*=\s*["\']?(?!data:|#)([^"\'\s>]+)', html)
    if outside:
        fail("the page refers to %s (it must be one file)" % outside[:3])

    work = tempfile.mkdtemp(prefix="abrade_report_")
    page = os.path.join(work, "report.html")
    with open(page, "w", encoding="utf-8") as f:
        f.write(html.replace("</body>", CHECK + "</body>"))
    profile = os.path.join(work, "profile")
    run = subprocess.run([browser] + FLAGS + ["--user-data-dir=" + profile, "--enable-logging=stderr", "--v=0",
                          "--virtual-time-budget=10000", "--dump-dom", "file://" + page],
                         capture_output=True, text=True, timeout=180)
    # console errors: uncaught exceptions, failed loads and console.error (not console.log text)
    errors = [l for l in run.stderr.splitlines()
              if ("CONSOLE" in l and (":ERROR:" in l or "Uncaught" in l)) or "Failed to load resource" in l
              or re.search(r"Uncaught \w*Error", l)]
    if errors:
        fail("console errors:\n  " + "\n  ".join(errors[:5]))
    m = re.search(r'<pre id="selfcheck">(.*?)</pre>', run.stdout, re.S)
    if not m:
        fail("the page did not finish loading (no check result); chromium said:\n" + run.stderr[-2000:])
    found = json.loads(m.group(1).replace("&quot;", '"').replace("&lt;", "<").replace("&gt;", ">").replace("&amp;", "&"))

    if found["resources"]:
        fail("the browser fetched %s (the page must be one file)" % found["resources"][:3])
    images = found["images"]
    if not images:
        fail("no images in the report")
    figures = set(i["figure"] for i in images)
    for f in filter(None, a.expect_figures.split(",")):
        if f not in figures:
            fail("no %s figure in the report (it has %s)" % (f, sorted(figures)))
    for img in images:
        if not img["ok"]:
            fail("image '%s' does not decode" % img["alt"])
        if not img["inline"]:
            fail("image '%s' is not inlined" % img["alt"])
        if img["spread"] <= 0:
            fail("image '%s' is blank (its pixels do not vary)" % img["alt"])
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
            # the number as a reader reads it: value and unit from the text, within three digits' rounding
            m = re.fullmatch(r"\s*([0-9.]+(?:e[+-]?[0-9]+)?) (t|kt|Mt)\s*", head["text"])
            if not m:
                fail("headline text %r is not a number of t, kt or Mt" % head["text"])
            read = float(m.group(1)) * {"t": 1, "kt": 1e3, "Mt": 1e6}[m.group(2)]
            if abs(read - expected) > 5e-3 * abs(expected) or float(m.group(1)) >= 1000 or float(m.group(1)) < 1:
                fail("headline text %r does not show summary.json's %r in its unit" % (head["text"], expected))
        print("ok: headline %s = summary.json's predicted_tonnes_to_end_of_life (%r)" % (head["text"], expected))
    elif head["id"] == "headline-w":
        cal = json.load(open(os.path.join(a.run, "calibration.json")))
        expected = cal["runs"][0]["archard_coefficient"]
        if abs(float(head["value"]) - expected) > 1e-9 * abs(expected):
            fail("headline W %s differs from calibration.json's %r" % (head["value"], expected))
        print("ok: headline W = calibration.json's (%r)" % expected)
    elif head["id"] == "headline-scale": # a calibration of runs without a wear coefficient (analytic rates)
        cal = json.load(open(os.path.join(a.run, "calibration.json")))
        expected = cal["runs"][0]["scale"]
        if abs(float(head["value"]) - expected) > 1e-9 * abs(expected):
            fail("headline scale %s differs from calibration.json's %r" % (head["value"], expected))
        print("ok: headline scale = calibration.json's (%r)" % expected)
    elif head["id"] == "headline-volume": # a part's preview (the knife job)
        expected = json.load(open(os.path.join(a.run, "summary.json")))["results"]["part"]["volume"]
        if abs(float(head["value"]) - expected) > 1e-9 * abs(expected):
            fail("headline volume %s differs from summary.json's %r" % (head["value"], expected))
        print("ok: headline volume = summary.json's (%r)" % expected)
    elif head["id"] == "headline-rms":
        cmp = json.load(open(os.path.join(a.run, "comparison.json")))
        expected = cmp["registration"]["rms_distance"]
        if abs(float(head["value"]) - expected) > 1e-9 * abs(expected):
            fail("headline RMS %s differs from comparison.json's %r" % (head["value"], expected))
        print("ok: headline RMS distance = comparison.json's (%r)" % expected)
    elif head["id"] == "headline-count":
        rows = sum(1 for l in open(os.path.join(a.run, "concepts.csv" if os.path.exists(os.path.join(a.run, "concepts.csv"))
                                                else "study.csv")) if l.strip()) - 1
        if int(head["value"]) != rows:
            fail("headline counts %s variants, the table has %d" % (head["value"], rows))
        print("ok: headline %s variants = the table's rows" % head["value"])
        # the significant changes in words: one item per 1 in a *_significant column (the first
        # row, the baseline, is not compared)
        import csv as csvmod
        table = list(csvmod.DictReader(open(os.path.join(a.run, "concepts.csv" if os.path.exists(
            os.path.join(a.run, "concepts.csv")) else "study.csv"))))
        want = sum(1 for r in table[1:] for k, v in r.items() if k.endswith("_significant") and v == "1")
        html = open(os.path.join(a.run, "report.html")).read()
        section = html[html.find(">Significant changes<"):]
        section = section[:section.find("<h2")] if "<h2" in section else section
        if ">Significant changes<" not in html:
            fail("no 'Significant changes' section")
        if section.count("<li>") != want:
            fail("the 'Significant changes' section lists %d changes, the table has %d" % (section.count("<li>"), want))
        print("ok: the significant changes listed (%d) = the table's" % want)
    else:
        print("ok: headline %s" % head["text"])

    if a.expect_face_table: # a part's preview: the face table is summary.json's, face by face
        faces = json.load(open(os.path.join(a.run, "summary.json")))["results"]["part"]["file_faces"]
        html = open(os.path.join(a.run, "report.html")).read()
        table = html[html.find(">Faces<"):]
        table = table[:table.find("</table>")]
        rows = [re.findall(r"<td>(.*?)</td>", r) for r in re.findall(r"<tr>(.*?)</tr>", table)]
        rows = [r for r in rows if r]
        if len(rows) != len(faces):
            fail("the face table has %d rows, summary.json %d faces" % (len(rows), len(faces)))
        for r, f in zip(rows, faces):
            if r[0] != str(f["id"]) or r[2] != f["role"] or abs(float(r[3]) - f["area"]) > 1e-3 * f["area"]:
                fail("face table row %r differs from summary.json's face %r" % (r[:4], f))
        print("ok: the face table = summary.json's %d faces (id, role, area)" % len(faces))
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
