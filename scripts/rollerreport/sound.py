"""The sound of a transient: a time series (contact force or surface velocity) resampled to 44.1 kHz, 16 bit.

Time scaling of non-dimensional scenes: a mode predicted at the non-dimensional frequency f_nd (cycles per unit
time) is heard at the SI pitch f_si of the printer roller (its CEA in SI units, docs/squeal.md section 7) when the
scene's time is stretched by s = f_nd / f_si seconds per unit time: t_audio = s t. SI scenes use s = 1. A
transient shorter than `min_seconds` of audio is looped (`loop`: Hann windows overlapped by half, the loop a whole
number of periods of its own loudest line) so that it can be heard; this keeps that line, the envelope becomes
periodic.
"""
import wave

import numpy as np

RATE = 44100


def audio_signal(t, y, seconds_per_unit=1.0, rate=RATE, min_seconds=1.0):
    """(samples in [-1, 1], rate): y(t) with the mean removed, on t_audio = seconds_per_unit * t, linearly
    resampled at `rate`, looped to at least `min_seconds` (see loop)."""
    t = np.asarray(t, float)
    y = np.asarray(y, float)
    ok = np.isfinite(t) & np.isfinite(y)
    t, y = t[ok], y[ok]
    ta = (t - t[0]) * seconds_per_unit
    n = max(int(ta[-1] * rate), 16)
    s = np.interp(np.arange(n) / rate, ta, y - y.mean())
    if n < min_seconds * rate:
        s = loop(s, rate, min_seconds)
    peak = np.max(np.abs(s))
    return (s / peak if peak > 0 else s), rate


def loop(s, rate, min_seconds):
    """A short signal repeated to `min_seconds`: its last 2 H samples under periodic Hann windows overlapped by
    H (the windows sum to 1), H a whole number of periods of the signal's own loudest line (measured on s, zero
    padded), so that the loop keeps that line: a repetition every H has lines only at multiples of rate / H, and
    one of them is then the signal's line (to the rounding of H to a sample). A loop of any other length would move
    the loudest line to the nearest multiple of rate / H (for a 10 ms transient, 200 Hz apart)."""
    n = len(s)
    f = loudest_line(s, rate, pad=16)
    periods = max(1, int((n / 2) * f / rate))
    hop = int(round(periods * rate / f))
    while 2 * hop > n and periods > 1:
        periods -= 1
        hop = int(round(periods * rate / f))
    if 2 * hop > n:  # shorter than two periods: the whole signal, not a whole number of periods
        hop = n // 2
    L = 2 * hop
    w = 0.5 - 0.5 * np.cos(2 * np.pi * np.arange(L) / L)
    seg = w * s[n - L :]
    copies = int(np.ceil(min_seconds * rate / hop)) + 1
    out = np.zeros(hop * (copies - 1) + L)
    for k in range(copies):
        out[k * hop : k * hop + L] += seg
    return out[hop : hop * copies]  # without the fade-in and fade-out halves: every sample is two windows' sum


def write_wav(path, samples, rate=RATE):
    """A mono 16-bit PCM WAV of samples in [-1, 1] (scaled to 0.9 of full scale)."""
    pcm = np.clip(np.round(np.asarray(samples) * 0.9 * 32767), -32768, 32767).astype("<i2")
    with wave.open(str(path), "wb") as w:
        w.setnchannels(1)
        w.setsampwidth(2)
        w.setframerate(rate)
        w.writeframes(pcm.tobytes())


def read_wav(path):
    """(samples as float in [-1, 1], rate) of a mono 16-bit WAV."""
    with wave.open(str(path), "rb") as w:
        rate = w.getframerate()
        data = np.frombuffer(w.readframes(w.getnframes()), dtype="<i2").astype(float) / 32768.0
    return data, rate


def loudest_line(samples, rate, fmin=20.0, pad=1):
    """The frequency (Hz) of the largest line of the Hann-windowed spectrum above fmin (zero padded to `pad` times
    the length), refined by parabolic interpolation of the log amplitude between bins."""
    x = np.asarray(samples, float) - np.mean(samples)
    m = int(pad * len(x))
    spec = np.abs(np.fft.rfft(x * np.hanning(len(x)), m))
    f = np.fft.rfftfreq(m, 1.0 / rate)
    spec[f < fmin] = 0.0
    k = int(np.argmax(spec))
    if 0 < k < len(spec) - 1 and spec[k - 1] > 0 and spec[k + 1] > 0:
        a, b, c = np.log(spec[k - 1 : k + 2])
        d = 0.5 * (a - c) / (a - 2 * b + c)
        return float(f[k] + d * (f[1] - f[0]))
    return float(f[k])


def spectrogram_png(path, samples, rate, pitch=None, title="Spectrogram"):
    """The spectrogram of the WAV's samples as a PNG; the predicted pitch as a dashed line."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(7, 3.5))
    nfft = 2048 if len(samples) >= 4096 else max(64, len(samples) // 4)
    _, _, _, im = ax.specgram(samples, NFFT=nfft, Fs=rate, noverlap=nfft // 2, cmap="magma")
    top = float(np.nanmax(im.get_array()))
    im.set_clim(top - 60, top)  # 60 dB below the loudest: the faint sidebands of the loop's envelope drop out
    fig.colorbar(im, ax=ax, label="dB")
    if pitch:
        ax.axhline(pitch, color="c", ls="--", lw=0.8, label=f"predicted {pitch:.0f} Hz")
        ax.set_ylim(0, min(rate / 2, 4 * pitch))
        ax.legend(loc="upper right")
    ax.set_xlabel("time (s)")
    ax.set_ylabel("frequency (Hz)")
    ax.set_title(title)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)
