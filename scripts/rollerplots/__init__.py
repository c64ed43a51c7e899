"""rollerplots: the figures of Roller's outputs (docs/output.md "Plotting"). Each module is a command,
`PYTHONPATH=scripts python3 -m rollerplots.NAME --help`:

- fields: |sigma| on the deformed roller, or the contact pressure along Gamma_C (HDF5 output);
- series: one monitor CSV column against t, runs overlaid, optionally against rollerref.axisym;
- spectrum: amplitude spectra of CSV columns with the element-passing frequency marked;
- sweep: eigenvalues of a -sweep CSV against one swept option (Campbell diagram, squeal maps);
- traction: pressure, traction and stick zone across the contact patch;
- carter: Carter's rolling contact (docs/friction.md 5.2); stickslip: docs/friction.md 5.3's figure;
- squeal_transient: the order-1 whirl of transients against the CEA (docs/squeal.md 4.2).
"""
__all__ = ["carter", "fields", "series", "spectrum", "squeal_transient", "stickslip", "sweep", "traction"]
