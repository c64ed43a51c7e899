"""The sound of a transient: the pressure at the listener (rollerreport.radiation) as a WAV of the simulated time.

- **Length**: the simulated span times the time scale (t_audio = s t, s the scene's seconds per unit time: 1 in SI
  scenes), never looped: a 16 ms transient is a 16 ms WAV. SPEC asks for at least MIN_SECONDS (0.5 s); a shorter
  span is written all the same and the report says so (`notice`).
- **Level**: a fixed reference, so that a quiet roller sounds quiet: a full-scale sine is 94 dB SPL (1 Pa rms,
  the calibrator's level; full scale = sqrt(2) Pa). A louder sound is written with the reference raised by whole
  10 dB steps until its peak fits, and the reference written is stated (`full_scale_db`).
- **Envelope**: the pressure's own, resampled linearly at 44.1 kHz (a decaying mode decays, a limit cycle is
  sustained).
"""
import math
import wave

import numpy as np

from .radiation import P_REF

RATE = 44100
MIN_SECONDS = 0.5  # SPEC section 10: squeal.wav from at least 0.5 s of simulated time
FULL_SCALE_DB = 94.0  # a full-scale sine is 94 dB SPL (1 Pa rms)


def full_scale_pa(db=FULL_SCALE_DB):
    """The peak pressure (Pa) of a full-scale sine of `db` dB SPL."""
    return math.sqrt(2) * P_REF * 10 ** (db / 20)


def resample(t_audio, y, rate=RATE):
    """y on t_audio (s, from 0), linearly resampled at `rate` over the span (no loop, no padding)."""
    t_audio = np.asarray(t_audio, float) - float(t_audio[0])
    n = max(int(math.floor(t_audio[-1] * rate)) + 1, 2)
    return np.interp(np.arange(n) / rate, t_audio, np.asarray(y, float))


def write_pressure_wav(path, t_audio, p, rate=RATE, full_scale_db=FULL_SCALE_DB):
    """The pressure p (Pa) on t_audio (s) as a mono 16-bit WAV whose full scale is a sine of full_scale_db dB SPL,
    raised by 10 dB steps while the peak does not fit. Returns {seconds, rate, full_scale_db, full_scale_pa,
    peak_pa, samples (as written, in Pa), notice}."""
    s = resample(t_audio, p, rate)
    peak = float(np.max(np.abs(s))) if len(s) else 0.0
    db = full_scale_db
    while peak > full_scale_pa(db):
        db += 10.0
    fs = full_scale_pa(db)
    pcm = np.clip(np.round(s / fs * 32767), -32768, 32767).astype("<i2")
    with wave.open(str(path), "wb") as w:
        w.setnchannels(1)
        w.setsampwidth(2)
        w.setframerate(rate)
        w.writeframes(pcm.tobytes())
    seconds = len(s) / rate
    return {"seconds": seconds, "rate": rate, "full_scale_db": db, "full_scale_pa": fs, "peak_pa": peak,
            "samples": s, "notice": notice(seconds)}


def notice(seconds):
    """The report's sentence when the WAV is shorter than MIN_SECONDS, else ''."""
    if seconds >= MIN_SECONDS:
        return ""
    return (f"squeal.wav holds the {seconds * 1e3:.1f} ms that were simulated, not looped: SPEC asks for at least "
            f"{MIN_SECONDS:g} s of simulated time; the long transients come with the reduced-order model (-rom, "
            "branch rom), not yet built")


def read_wav(path):
    """(samples as float in [-1, 1], rate) of a mono 16-bit WAV."""
    with wave.open(str(path), "rb") as w:
        rate = w.getframerate()
        data = np.frombuffer(w.readframes(w.getnframes()), dtype="<i2").astype(float) / 32768.0
    return data, rate


def loudest_line(samples, rate, fmin=20.0, pad=1, fmax=None):
    """The frequency (Hz) of the largest line of the Hann-windowed spectrum within fmin <= f <= fmax (zero padded to
    `pad` times the length), refined by parabolic interpolation of the log amplitude between bins."""
    x = np.asarray(samples, float) - np.mean(samples)
    m = int(pad * len(x))
    spec = np.abs(np.fft.rfft(x * np.hanning(len(x)), m))
    f = np.fft.rfftfreq(m, 1.0 / rate)
    spec[(f < fmin) | (f > (fmax if fmax is not None else np.inf))] = 0.0
    k = int(np.argmax(spec))
    if 0 < k < len(spec) - 1 and spec[k - 1] > 0 and spec[k + 1] > 0:
        a, b, c = np.log(spec[k - 1 : k + 2])
        d = 0.5 * (a - c) / (a - 2 * b + c)
        return float(f[k] + d * (f[1] - f[0]))
    return float(f[k])


def envelope_rate(samples, rate, f0, periods=2.0):
    """The growth rate (1/s) of the envelope of a tone at f0: the slope of log RMS over windows of `periods`
    periods (a decaying mode: negative, a sustained cycle: about 0)."""
    m = max(4, int(round(periods * rate / f0)))
    x = np.asarray(samples, float)
    k = len(x) // m
    if k < 3:
        return math.nan
    rms = np.sqrt(np.mean(x[: k * m].reshape(k, m) ** 2, axis=1))
    ok = rms > 0
    tc = (np.arange(k) + 0.5) * m / rate
    return float(np.polyfit(tc[ok], np.log(rms[ok]), 1)[0]) if ok.sum() >= 3 else math.nan


def spectrogram_png(path, samples_pa, rate, pitch=None, title="Spectrogram at the listener"):
    """The spectrogram of the pressure (Pa) in dB SPL (re 20 uPa) as a PNG, 60 dB below its loudest bin; the
    predicted pitch as a dashed line."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    x = np.asarray(samples_pa, float)
    fig, ax = plt.subplots(figsize=(7, 3.5))
    nfft = 2048 if len(x) >= 8192 else max(64, 2 ** int(math.log2(max(len(x) // 4, 64))))
    # psd in Pa^2/Hz -> dB re P_REF^2/Hz
    _, _, _, im = ax.specgram(x / P_REF, NFFT=nfft, Fs=rate, noverlap=3 * nfft // 4, cmap="magma", scale="dB")
    top = float(np.nanmax(im.get_array()))
    im.set_clim(top - 60, top)
    fig.colorbar(im, ax=ax, label="dB re (20 uPa)^2/Hz")
    if pitch:
        ax.axhline(pitch, color="c", ls="--", lw=0.8, label=f"predicted {pitch:.0f} Hz")
        ax.set_ylim(0, min(rate / 2, 4 * pitch))
        ax.legend(loc="upper right")
    ax.set_xlabel("time (s, the simulated span)")
    ax.set_ylabel("frequency (Hz)")
    ax.set_title(title, fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)
