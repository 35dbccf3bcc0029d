#!/usr/bin/env python3
"""Browser test of `amp view` pages: they load, draw, and the robot moves.

    viewer_browser_check.py PAGE.html [PAGE2.html ...] [--save DIR]
    viewer_browser_check.py --self-test   # on viewer_fixture_page.py pages

For each page, in headless Chromium (software WebGL): wait for
document.body.dataset.ampReady, move the #amp-frame slider as a user would
(value + 'input' event) to frame 0, the last frame and the middle one, and
screenshot. The robot is found by its orange colour (#ff7f0e under any
shading); it must be visible at the first and last frames and must have
moved between them. Any console error, uncaught exception or error log
entry fails the page.

Exit 0 when every page passes, 1 with one line per failure, 77 (CTest's
skip code) when Chromium is not installed. Stdlib only: the screenshots are
decoded here rather than with PIL.
"""
import argparse
import struct
import sys
import tempfile
import time
import zlib
from pathlib import Path

sys.dont_write_bytecode = True  # leave no __pycache__ in the source tree
sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts"))
from chromium_page import ChromiumPage, PageError, find_chromium, parse_size  # noqa: E402

SKIP = 77
# Robot colour window. #ff7f0e is hue 28 deg. A translucent ghost drawn over
# the robot shifts it: the green start ghost at opacity 0.3 to 44 deg (57 at
# opacity 0.5), a red/purple goal ghost towards 20. Shading changes value,
# not hue, so value is loose; greys, the blue trace and white never match.
HUE_MIN, HUE_MAX = 8.0, 56.0
SAT_MIN, VAL_MIN = 0.45, 0.20


# ---- PNG decoding (8-bit RGB/RGBA, non-interlaced: what Chromium writes) ----
def _chunks(data):
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("not a PNG")
    pos = 8
    while pos < len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        yield kind, data[pos + 8:pos + 8 + n]
        pos += 12 + n


def _add_bytes(a, b):
    """Bytewise (a + b) mod 256 of two equal-length rows, via one big-int
    SWAR addition (carries never cross bytes): the fast path for 'Up' rows,
    which are most of Chromium's."""
    n = len(a)
    x, y = int.from_bytes(a, "little"), int.from_bytes(b, "little")
    low7 = int.from_bytes(b"\x7f" * n, "little")
    high = int.from_bytes(b"\x80" * n, "little")
    return ((x & low7) + (y & low7) ^ ((x ^ y) & high)).to_bytes(n, "little")


def _unfilter(kind, line, prev, bpp):
    if kind == 0:
        return bytes(line)
    if kind == 2:
        return _add_bytes(line, prev)
    out = bytearray(line)
    for i in range(len(out)):
        a = out[i - bpp] if i >= bpp else 0
        if kind == 1:
            out[i] = (out[i] + a) & 255
        elif kind == 3:
            out[i] = (out[i] + ((a + prev[i]) >> 1)) & 255
        else:  # 4: Paeth
            b, c = prev[i], prev[i - bpp] if i >= bpp else 0
            p = a + b - c
            pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
            pred = a if pa <= pb and pa <= pc else b if pb <= pc else c
            out[i] = (out[i] + pred) & 255
    return bytes(out)


def decode_png(data):
    """(width, height, rows): rows are bytes of R, G, B per pixel."""
    idat = []
    for kind, body in _chunks(data):
        if kind == b"IHDR":
            w, h, depth, color, _, _, interlace = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat.append(body)
    if depth != 8 or color not in (2, 6) or interlace:
        raise ValueError(f"unsupported PNG (depth {depth}, colour type {color})")
    bpp = 3 if color == 2 else 4
    raw, stride = zlib.decompress(b"".join(idat)), w * bpp + 1
    rows, prev = [], bytes(w * bpp)
    for y in range(h):
        line = raw[y * stride + 1:(y + 1) * stride]
        prev = _unfilter(raw[y * stride], line, prev, bpp)
        rows.append(prev if bpp == 3 else bytes(b for i, b in enumerate(prev) if i % 4 != 3))
    return w, h, rows


# ---- robot pixels ------------------------------------------------------------
# Where to look: the largest canvas (the WebGL one), minus the boxes of page
# elements drawn over it (controls, legends, error boxes). Real pages have an
# orange legend swatch and brownish-orange notes, which must not count as
# robot. Overlays as large as half the canvas are taken for transparent
# layers and not masked.
REGION_JS = """(() => {
  const cs = [...document.querySelectorAll('canvas')];
  if (!cs.length) return null;
  const c = cs.reduce((a, b) => a.width * a.height >= b.width * b.height ? a : b);
  const r = c.getBoundingClientRect(), big = r.width * r.height / 2, ui = [];
  for (const el of document.body.querySelectorAll('*')) {
    if (el.contains(c) || ['SCRIPT', 'STYLE'].includes(el.tagName)) continue;
    const b = el.getBoundingClientRect();
    if (b.width > 0 && b.height > 0 && b.width * b.height < big)
      ui.push([b.left, b.top, b.right, b.bottom].map(Math.round));
  }
  return {canvas: [r.left, r.top, r.right, r.bottom].map(Math.round), ui: ui};
})()"""


def robot_pixels(png, region=None):
    """Set of y*width+x of the orange pixels in `region`, and the image width."""
    w, h, rows = decode_png(png)
    x0, y0, x1, y1 = region["canvas"] if region else (0, 0, w, h)
    x0, y0, x1, y1 = max(x0, 0), max(y0, 0), min(x1, w), min(y1, h)
    ui = region["ui"] if region else []
    lo, hi = HUE_MIN / 60.0, HUE_MAX / 60.0
    vmin = VAL_MIN * 255
    found = set()
    for y in range(y0, y1):
        row = rows[y][3 * x0:3 * x1]
        for x, (r, g, b) in enumerate(zip(row[0::3], row[1::3], row[2::3]), x0):
            # Hue in [0, 60) means r >= g >= b; the cheap test drops the
            # greys and whites (most pixels) before any division.
            if r > b and r >= g >= b and r >= vmin:
                span = r - b
                if span >= SAT_MIN * r and lo * span <= g - b <= hi * span and \
                        not any(u[0] <= x < u[2] and u[1] <= y < u[3] for u in ui):
                    found.add(y * w + x)
    return found, w


def centroid(pixels, w):
    n = len(pixels)
    return (sum(p % w for p in pixels) / n, sum(p // w for p in pixels) / n)


def compare(first, last, w):
    """Centroid shift in pixels and Jaccard overlap of two pixel sets."""
    (x0, y0), (x1, y1) = centroid(first, w), centroid(last, w)
    shift = ((x1 - x0) ** 2 + (y1 - y0) ** 2) ** 0.5
    return shift, len(first & last) / len(first | last)


# ---- one page ----------------------------------------------------------------
def shoot(page, frame, shots, save, name):
    """Move the slider to `frame`, check the viewer followed, screenshot."""
    got = page.set_frame(frame)
    if got != frame:
        raise PageError(f"slider set to {frame} but ampViewer.frame is {got}")
    png = page.screenshot()
    if save:
        Path(save, f"{name}.frame{frame}.png").write_bytes(png)
    shots[frame] = png


def drive(path, args):
    """Screenshots at first, last and middle frames, and the page's errors.

    A failure also names the page's first error, its likely cause."""
    with ChromiumPage(args.size, args.timeout) as page:
        try:
            return _drive(page, path, args)
        except PageError as exc:
            first = page.errors[0] if page.errors else None
            raise PageError(f"{exc}; page error: {first}" if first and first not in str(exc)
                            else str(exc)) from None


def _drive(page, path, args):
    """Check the contract's wiring, then screenshot the three frames."""
    page.open(path)
    page.wait_ready(stop_on_error=True)
    count = page.frame_count()
    top = page.evaluate("(() => { const s = document.getElementById('amp-frame');"
                        " return s ? Number(s.max) : null; })()")
    if not isinstance(count, int) or count < 2:
        raise PageError(f"ampViewer.frameCount is {count!r}, need >= 2")
    if top != count - 1:
        raise PageError(f"#amp-frame max is {top}, expected frameCount-1 = {count - 1}")
    region = page.evaluate(REGION_JS)
    if not region or region["canvas"][2] <= region["canvas"][0] \
            or region["canvas"][3] <= region["canvas"][1]:
        raise PageError("no visible canvas on the page")
    shots = {}
    for frame in (0, count - 1, (count - 1) // 2):
        shoot(page, frame, shots, args.save, Path(path).stem)
    lost = [w for w in page.warnings if "CONTEXT_LOST" in w]
    return count, shots, region, page.errors + lost, len(page.warnings)


def judge(count, shots, region, args):
    """Reasons the pictures fail, and a summary of what was measured."""
    first, w = robot_pixels(shots[0], region)
    last, _ = robot_pixels(shots[count - 1], region)
    mid, _ = robot_pixels(shots[(count - 1) // 2], region)
    summary = f"robot px first={len(first)} mid={len(mid)} last={len(last)}"
    reasons = [f"only {len(s)} robot pixels at the {n} frame (need {args.min_pixels})"
               for n, s in (("first", first), ("last", last)) if len(s) < args.min_pixels]
    if reasons:
        return reasons, summary
    shift, overlap = compare(first, last, w)
    summary += f", centroid shift {shift:.1f} px, overlap {overlap:.2f}"
    if overlap >= args.max_overlap and shift <= args.min_shift:
        reasons.append(f"robot did not move (overlap {overlap:.2f}, shift {shift:.1f} px)")
    return reasons, summary


def check_page(path, args):
    """One output line for the page; True when it passes."""
    start, name = time.monotonic(), Path(path).name
    try:
        count, shots, region, errors, n_warn = drive(path, args)
        reasons, summary = judge(count, shots, region, args)
    except (PageError, ValueError, OSError) as exc:
        print(f"FAIL {name}: {exc}")
        return False
    reasons = [f"page error: {e}" for e in errors] + reasons
    took = time.monotonic() - start
    print(f"{'FAIL' if reasons else 'PASS'} {name}: {count} frames, {summary}, "
          f"errors {len(errors)}, warnings {n_warn} ({took:.1f} s)")
    for r in reasons:
        print(f"  {name}: {r}")
    return not reasons


def self_test(args):
    """The check must pass the good fixture and fail the broken and static ones."""
    sys.path.insert(0, str(Path(__file__).resolve().parent))
    from viewer_fixture_page import build_page
    expected = {"good": True, "broken": False, "static": False}
    with tempfile.TemporaryDirectory(prefix="amp-viewer-") as tmp:
        got = {}
        for mode in expected:
            page = Path(tmp, f"fixture-{mode}.html")
            try:
                page.write_text(build_page(mode), encoding="utf-8")
            except OSError as exc:  # no libjs-three: nothing to test with
                print(f"SKIP: cannot build the fixture pages ({exc})")
                return SKIP
            got[mode] = check_page(page, args)
    wrong = [m for m in expected if got[m] != expected[m]]
    for mode in wrong:
        print(f"SELF-TEST FAIL: the {mode} fixture was "
              f"{'passed' if got[mode] else 'failed'}")
    if not wrong:
        print("self-test ok: good fixture passed, broken and static fixtures failed")
    return 1 if wrong else 0


def main():
    ap = argparse.ArgumentParser(description="Check `amp view` pages in headless Chromium.")
    ap.add_argument("pages", nargs="*")
    ap.add_argument("--self-test", action="store_true",
                    help="run on generated good/broken/static fixture pages")
    ap.add_argument("--size", default="800x600", type=parse_size, help="viewport WxH")
    ap.add_argument("--timeout", type=float, default=60.0,
                    help="seconds per wait (software WebGL is slow)")
    ap.add_argument("--min-pixels", type=int, default=100,
                    help="robot pixels needed at the first and last frames")
    ap.add_argument("--max-overlap", type=float, default=0.9,
                    help="moved if the Jaccard overlap is below this ...")
    ap.add_argument("--min-shift", type=float, default=3.0,
                    help="... or the centroid moved more pixels than this")
    ap.add_argument("--save", metavar="DIR", help="keep the screenshots here")
    args = ap.parse_args()
    if not find_chromium():
        print("SKIP: chromium not installed (or AMP_CHROMIUM not found)")
        return SKIP
    if args.save:
        Path(args.save).mkdir(parents=True, exist_ok=True)
    if args.self_test:
        return self_test(args)
    if not args.pages:
        ap.error("no pages given (or use --self-test)")
    results = [check_page(p, args) for p in args.pages]
    return 0 if all(results) else 1


if __name__ == "__main__":
    sys.exit(main())
