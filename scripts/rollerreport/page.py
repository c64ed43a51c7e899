"""report.html beside report.md: the verdict, the mechanisms, an audio player for squeal.wav, the map, the
spectrogram, the animation and the cost, every file by a relative link (the folder can be moved or served as is)."""
import html
import os

STYLE = """body{font-family:sans-serif;max-width:70em;margin:1em auto;padding:0 1em;color:#222}
table{border-collapse:collapse;margin:.5em 0}td,th{border:1px solid #bbb;padding:.2em .5em;text-align:left;vertical-align:top}
.notice{background:#fff4d6;border-left:4px solid #e0a000;padding:.4em .8em}.yes{color:#b00;font-weight:bold}
img,video{max-width:100%}code{background:#f3f3f3}"""


def _e(x):
    return html.escape(str(x))


def _fmt(x, spec=".4g"):
    if x is None:
        return "-"
    try:
        return format(float(x), spec)
    except (TypeError, ValueError):
        return _e(x)


def write(folder, out, name="report.html"):
    """Write the page from the report's dict `out` (report.json's content); returns its file name."""
    has = lambda f: os.path.exists(os.path.join(folder, f))  # noqa: E731
    scene = out.get("scene", {})
    body = [f"<h1>Squeak report: {_e(scene.get('name', ''))}</h1>"]
    word = out.get("verdict", "")
    by = out.get("squeals_by") or []
    body.append(f"<h2>Verdict</h2><p>The roller <b class='{'yes' if word == 'squeals' else ''}'>{_e(word)}</b>"
                + (f" by {_e(' and '.join(by))}" if by else "")
                + ("" if out.get("verdict_complete") else " &mdash; from the mechanisms that ran; not every mechanism "
                   "ran (below)") + ".</p>")
    rows = ["<tr><th>mechanism</th><th>status</th><th>squeals</th><th>frequency (Hz)</th><th>growth (1/s)</th>"
            "<th>limit cycle</th><th>level (dB)</th><th>evidence</th></tr>"]
    for m in out.get("mechanisms", []):
        sq = {True: "yes", False: "no", None: "-"}[m.get("squeals")]
        rows.append(f"<tr><td>{_e(m['kind'])}</td><td>{_e(m['status'])}</td><td>{sq}</td><td>{_fmt(m.get('frequency_hz'), '.1f')}</td>"
                    f"<td>{_fmt(m.get('growth_rate_per_s'))}</td><td>{_fmt(m.get('limit_cycle_amplitude'))}</td>"
                    f"<td>{_fmt(m.get('spl_db'), '.1f')}</td><td>{'<br>'.join(_e(x) for x in m.get('evidence', []))}</td></tr>")
    body.append("<h2>Mechanisms</h2><table>" + "".join(rows) + "</table>")
    body += [f"<p>{_e(m['kind'])}'s level: {_e(m['spl_note'])}.</p>" for m in out.get("mechanisms", []) if m.get("spl_note")]
    snd = out.get("sound") or {}
    if has("squeal.wav"):
        lis = out.get("listener", {})
        src = out.get("wav_source", {})
        body.append("<h2>The sound</h2>")
        body.append(f"<audio id='squeal' controls preload='auto' src='squeal.wav'></audio>")
        body.append(f"<p>At {_fmt(lis.get('distance_m'), 'g')} m from a {_fmt(lis.get('width_m', 0) * 1e3, 'g')} mm wide roller "
                    f"({_fmt(lis.get('angle_deg'), 'g')} degrees): <b>{_fmt(out.get('spl_db'), '.1f')} dB SPL</b> (loudest 125 ms), "
                    f"{_fmt(snd.get('spl_dba'), '.1f')} dB(A); the WAV's loudest line {_fmt(snd.get('loudest_hz'), '.1f')} Hz. "
                    f"squeal.wav holds {_fmt(out.get('wav_seconds', 0) * 1e3, '.1f')} ms: the simulated span "
                    f"{_fmt(src.get('t0'), '.4g')} to {_fmt(src.get('t1'), '.4g')} of {_e(src.get('file'))} "
                    f"({_e(src.get('column'))}) times {_fmt(src.get('seconds_per_unit'), '.4g')} s per unit; full scale "
                    f"is a sine of {_fmt(snd.get('wav_reference', {}).get('full_scale_db_spl'), 'g')} dB SPL.</p>")
        for note in (snd.get("notice"), snd.get("level_note")):
            if note:
                body.append(f"<p class='notice'>{_e(note)}</p>")
    if has("spectrogram.png"):
        body.append("<img src='spectrogram.png' alt='spectrogram'>")
    anim = out.get("animation") or {}
    gif = next((f for f in anim.get("files", []) if f.endswith(".gif")), None)
    if gif and has(gif):
        mp4 = next((f for f in anim.get("files", []) if f.endswith(".mp4")), None)
        body.append("<h2>The vibration</h2>" + f"<img src='{_e(gif)}' alt='the roller vibrating'>"
                    + f"<p>{_e(anim.get('reference', ''))}, magnified {_fmt(anim.get('magnification'), '.3g')} times"
                    + (f"; also as <a href='{_e(mp4)}'>{_e(mp4)}</a>" if mp4 and has(mp4) else "") + ".</p>")
    if has("map.png"):
        body.append("<h2>The map</h2><img src='map.png' alt='the squeal map'>")
    if has("disturbances.png"):
        body.append("<h2>Kicks about the steady state</h2><img src='disturbances.png' alt='kicks of growing size about the steady state'>")
    if has("ripple_sweep.png"):
        body.append("<h2>The drive's ripple swept</h2><img src='ripple_sweep.png' alt='the forced response against the ripple frequency'>")
    prop = out.get("propensity", {})
    if prop.get("status") == "run":
        lo, hi = prop["confidence_95"]
        body.append(f"<h2>Propensity</h2><p>{_e(prop['cases'])} cases (Latin hypercube, seed {_e(prop['sampling']['seed'])}, "
                    f"<a href='propensity.csv'>propensity.csv</a>): <b>{100 * prop['fraction']:.1f} % squeak</b> (95 %: "
                    f"{100 * lo:.1f}-{100 * hi:.1f} %); classified by {_e(prop['classifier'])}. Ranked: "
                    + ", ".join(f"{_e(e['parameter'])} {e['spearman']:+.2f}" for e in prop["ranking"]) + ".</p>")
        if prop.get("validity"):
            body.append(f"<p><i>Validity: {_e(prop['validity'])}.</i></p>")
        if has("propensity.png"):
            body.append("<img src='propensity.png' alt='the propensity study'>")
    else:
        body.append(f"<h2>Propensity</h2><p>{_e(prop.get('status', ''))} ({_e(prop.get('cases', 0))} cases).</p>")
    if out.get("cost"):
        rows = ["<tr><th>part</th><th>status</th><th>CPU (s)</th><th>wall (s)</th><th>ranks</th><th>reused</th></tr>"]
        for part, p in out["cost"].items():
            rows.append(f"<tr><td>{_e(part)}</td><td>{_e(p.get('status'))}</td><td>{_fmt(p.get('cpu_seconds'), '.1f')}</td>"
                        f"<td>{_fmt(p.get('wall_seconds'), '.1f')}</td><td>{_e(p.get('ranks', 1))}</td><td>{'yes' if p.get('reused') else 'no'}</td></tr>")
        body.append("<h2>Cost</h2><table>" + "".join(rows) + "</table>")
    links = ["report.md", "report.json"] + [f for f in ("commands.json", "journal.json") if has(f)]  # report.json: next
    body.append("<p>" + " &middot; ".join(f"<a href='{f}'>{f}</a>" for f in links) + "</p>")
    page = (f"<!DOCTYPE html><html><head><meta charset='utf-8'><title>Squeak report: {_e(scene.get('name', ''))}</title>"
            f"<style>{STYLE}</style></head><body>\n" + "\n".join(body) + "\n</body></html>\n")
    with open(os.path.join(folder, name), "w") as f:
        f.write(page)
    return name
