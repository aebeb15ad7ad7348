#!/usr/bin/python3
"""`biphasic schema --json` against a standard validator (Debian's python3-jsonschema): the
schema is valid draft-07, every case file shipped in cases/ validates against it, and broken
case files are rejected by the schema, naming the key, and by `biphasic check` alike.

usage: test_case_json_schema.py (BIPHASIC_BIN = the program)
"""
import json
import os
import pathlib
import subprocess
import sys
import tempfile
import tomllib

import jsonschema

ROOT = pathlib.Path(__file__).resolve().parents[2]
BIN = os.environ["BIPHASIC_BIN"]

# A valid case to break: the paper's mesh-1 case.
BASE = (ROOT / "cases/paper/mesh1_k1e-3_nogls.toml").read_text()
BROKEN = {
    # name: (text, key path the validator must name)
    "unknown key": (BASE.replace("[mesh]\n", "[mesh]\nradious = 18.0\n", 1), "mesh"),
    "wrong type": (BASE.replace("[output]\n", "[output]\nfields = \"yes\"\n", 1), "fields"),
    "out of range": (BASE.replace("mu = 0.5", "mu = -0.5", 1), "mu"),
    "not a choice": (BASE.replace("[linear_solver]\ntype = \"mumps\"",
                                  "[linear_solver]\ntype = \"lu\"", 1), "type"),
    "symmetry with a value": (BASE + "\n[[boundary]]\nname = \"symmetry_x\"\ntype = \"symmetry\"\n"
                              "value = 1.0\n", "boundary"),
    "displacement without component": (BASE + "\n[[boundary]]\nname = \"bottom\"\n"
                                       "type = \"displacement\"\nvalue = 0.0\n", "boundary"),
    "rigid platen without force": (BASE + "\n[[boundary]]\nname = \"top\"\n"
                                   "type = \"rigid_platen\"\ncomponent = \"z\"\n", "boundary"),
}


def main():
    out = subprocess.run([BIN, "schema", "--json"], capture_output=True, text=True, check=True)
    schema = json.loads(out.stdout)
    jsonschema.Draft7Validator.check_schema(schema)
    validator = jsonschema.Draft7Validator(schema)
    failures = []

    cases = sorted((ROOT / "cases").rglob("*.toml"))
    count = 0
    for path in cases:
        data = tomllib.loads(path.read_text())
        if "format_version" not in data:
            continue  # a study file, not a case
        count += 1
        errors = sorted(validator.iter_errors(data), key=lambda e: list(e.path))
        for e in errors:
            failures.append(f"{path.relative_to(ROOT)}: {'.'.join(map(str, e.path))}: {e.message}")
    if count < 20:
        failures.append(f"only {count} case files found under cases/")
    print(f"{count} shipped case files validated")

    for name, (text, key) in BROKEN.items():
        if text == BASE:
            failures.append(f"{name}: the base case did not change (test set-up)")
            continue
        errors = list(validator.iter_errors(tomllib.loads(text)))
        if not errors:
            failures.append(f"{name}: accepted by the schema")
            continue
        where = " ".join(".".join(map(str, e.absolute_path)) + " " + e.message for e in errors)
        if key not in where:
            failures.append(f"{name}: the schema's errors do not name '{key}': {where}")
        with tempfile.NamedTemporaryFile("w", suffix=".toml", delete=False) as f:
            f.write(text)
        try:
            check = subprocess.run([BIN, "check", f.name], capture_output=True, text=True)
        finally:
            os.unlink(f.name)
        if check.returncode != 1:
            failures.append(f"{name}: biphasic check exited {check.returncode}, not 1")
        print(f"{name}: rejected ({errors[0].message[:80]})")

    if failures:
        print("\n".join(failures))
        sys.exit(1)


if __name__ == "__main__":
    main()
