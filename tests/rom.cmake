# The reduced-order transient (-rom, docs/performance.md "Reduced-order transient"), without contact: the reduced
# model's eigenvalues below the cutoff against the full model's (0.1 %), its energy balance to round-off, and its
# transient against the full one (about 40 s)
roller_test(rom_free rom_free.py LABELS quick TIMEOUT 600)
