"""The Python of scripts/ lives in importable packages (rollerref, rollerreport, rollerplots, rollertools): every
module imports, and every command module answers `python3 -m PACKAGE.MODULE --help` (exit 0, its usage printed);
no loose .py file is left in scripts/ (the callers in tests/, bench/, docs/ and jobs/ use the `-m` commands)."""
import glob
import importlib
import os
import subprocess
import sys

from rollertest import SCRIPTS, Checker

PACKAGES = ("rollerref", "rollerreport", "rollerplots", "rollertools")
RUNS_AT_IMPORT = {"rollertools.options_table", "rollerref.__main__", "rollerreport.__main__"}  # commands only

c = Checker("scripts_packages")
loose = sorted(os.path.basename(p) for p in glob.glob(os.path.join(SCRIPTS, "*.py")))
c.check(not loose, f"no loose Python file in scripts/ ({', '.join(loose) or 'none'})")
for package in PACKAGES:
    files = sorted(glob.glob(os.path.join(SCRIPTS, package, "*.py")))
    c.check(os.path.join(SCRIPTS, package, "__init__.py") in files, f"{package} is a package ({len(files)} files)")
    for path in files:
        name = f"{package}.{os.path.splitext(os.path.basename(path))[0]}".replace(".__init__", "")
        if name in RUNS_AT_IMPORT:
            continue
        try:
            importlib.import_module(name)
            ok, why = True, ""
        except Exception as e:  # noqa: BLE001  (any import error is the failure reported)
            ok, why = False, f": {type(e).__name__}: {e}"
        c.check(ok, f"import {name}{why}")
        source = open(path).read()
        if "argparse" in source and '__name__ == "__main__"' in source or name.endswith("__main__"):
            p = subprocess.run([sys.executable, "-m", name, "--help"], capture_output=True, text=True, timeout=120)
            c.check(p.returncode == 0 and "usage" in p.stdout.lower(),
                    f"python3 -m {name} --help exits {p.returncode}{(': ' + p.stderr.strip()[-200:]) if p.returncode else ''}")
c.close()
