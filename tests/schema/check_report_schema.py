#!/usr/bin/env python3
"""Checks that every report.json BladeAxis writes conforms to docs/report.schema.json.

Three parts, all of which must pass:
  1. the golden expectations tests/golden/*/expect/report.json;
  2. fresh reports: the built bladeaxis run on a few jobs (the demo with and without --compare
     and --analyse-only, --json on standard output, a job file with layer edits, a machine with
     backlash on every axis, G-code, APT and point-table inputs) into a temporary folder, so
     that a key the C++ code starts writing fails here until the schema describes it;
  3. a negative self-check: copies of a valid report with an unknown key or without a required
     key must be rejected, which proves the schema is not vacuous.

Run by ctest `schema.report_json` (tests/schema/CMakeLists.txt) with Debian's python3-jsonschema:
  /usr/bin/python3 check_report_schema.py --source-dir REPO --bladeaxis BUILD/app/bladeaxis
"""

import argparse
import copy
import json
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

try:
    from jsonschema import Draft202012Validator
except ImportError:  # CMake only registers the test when this import works
    sys.exit("check_report_schema: python3-jsonschema is missing (apt install python3-jsonschema)")

# One run must not take long (the demo takes about a second); a hang is a failure, not a wait.
RUN_TIMEOUT_S = 300


def parse_arguments():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--source-dir", type=Path, required=True,
                        help="repository root (docs/, tests/golden, tests/data, resources/)")
    parser.add_argument("--bladeaxis", type=Path, required=True,
                        help="the built bladeaxis executable")
    parser.add_argument("--schema", type=Path,
                        help="schema to check against (default: SOURCE/docs/report.schema.json)")
    parser.add_argument("--work-dir", type=Path,
                        help="where the temporary output folder is made (default: system temp)")
    arguments = parser.parse_args()
    if arguments.schema is None:
        arguments.schema = arguments.source_dir / "docs" / "report.schema.json"
    return arguments


# --- validation -------------------------------------------------------------------------------

def load_validator(schema_path):
    schema = json.loads(schema_path.read_text(encoding="utf-8"))
    # A schema with a typo (e.g. "type": "numbr") would otherwise fail every document, or none.
    Draft202012Validator.check_schema(schema)
    return schema, Draft202012Validator(schema)


def schema_errors(validator, document):
    """The document's violations as (path, validator keyword, message), deepest path first."""
    errors = sorted(validator.iter_errors(document), key=lambda e: list(e.absolute_path))
    return [(list(error.absolute_path), error.validator, error.message) for error in errors]


def check_document(validator, document, label):
    """Prints the verdict for one report; True when it conforms."""
    errors = schema_errors(validator, document)
    if not errors:
        print(f"ok      {label}")
        return True
    print(f"FAILED  {label}: {len(errors)} violation(s)")
    for path, _, message in errors[:20]:  # enough to see the pattern, not a wall of text
        print(f"          at /{'/'.join(map(str, path))}: {message}")
    return False


def read_json(path):
    return json.loads(path.read_text(encoding="utf-8"))


# --- 1. golden expectations -------------------------------------------------------------------

def golden_reports(source_dir):
    return sorted((source_dir / "tests" / "golden").glob("*/expect/report.json"))


# --- 2. fresh reports from the built executable -----------------------------------------------

def machine_with_backlash(source_dir, folder):
    """The default blade machine with play on every axis, so that lost_motion has linear (_mm)
    and rotary (_deg) entries: the default machine only gives A backlash."""
    machine = read_json(source_dir / "resources" / "machines" / "blade_ab.json")
    for name, axis in machine["axes"].items():
        unit = "deg" if name in ("A", "B") else "mm"
        axis[f"backlash_{unit}"] = 0.01
    path = folder / "machine_with_backlash.json"
    path.write_text(json.dumps(machine, indent=2), encoding="utf-8")
    return path


def demo_job_with_layer_edit(folder):
    """A job file for the demo with one layer edit: only edits make rescheduled.edited_layers."""
    job = {"schema": "bladeaxis-job/1", "demo": True,
           "layer_edits": [{"layer": 1, "margin_deg": 2}]}
    path = folder / "demo_with_edit.json"
    path.write_text(json.dumps(job, indent=2), encoding="utf-8")
    return path


def fresh_jobs(source_dir, folder):
    """(name, arguments, where the report is): 'dir' = OUT/report.json, 'stdout' = --json."""
    data = source_dir / "tests" / "data"
    return [
        ("demo", ["--batch", "--demo"], "dir"),
        ("demo_compare", ["--batch", "--demo", "--compare"], "dir"),
        ("demo_analyse_only", ["--batch", "--demo", "--analyse-only"], "dir"),
        ("demo_json_stdout", ["--batch", "--demo", "--json"], "stdout"),
        ("demo_layer_edit", ["--batch", "--job", str(demo_job_with_layer_edit(folder))], "dir"),
        ("gcode_backlash", ["--batch", str(data / "programs" / "naca_weak_3rev.nc"),
                            "--tool-radius", "8",
                            "--machine", str(machine_with_backlash(source_dir, folder))], "dir"),
        ("apt", ["--batch", str(data / "programs" / "turbine_2rev.cls")], "dir"),
        ("table", ["--batch", str(data / "awkward" / "points_with_feed.csv"),
                   "--tool-radius", "8"], "dir"),
        # A table-B machine: the report adds axis_letters and machine_layout.
        ("demo_table_b", ["--batch", "--demo", "--machine",
                          str(source_dir / "resources" / "machines" / "table_b_head_a.json")],
         "dir"),
    ]


def run_job(executable, name, arguments, source, folder):
    """Runs one job; returns its report document, or None (with the reason printed)."""
    out_dir = folder / name
    command = [str(executable), *arguments]
    if source == "dir":
        command += ["--out", str(out_dir)]
    try:
        done = subprocess.run(command, capture_output=True, text=True, timeout=RUN_TIMEOUT_S,
                              check=False)
    except (OSError, subprocess.TimeoutExpired) as error:
        print(f"FAILED  fresh {name}: {error}")
        return None
    if done.returncode != 0:
        print(f"FAILED  fresh {name}: exit code {done.returncode}\n"
              f"          command: {' '.join(command)}\n          stderr: {done.stderr.strip()}")
        return None
    try:
        if source == "stdout":
            return json.loads(done.stdout)
        return read_json(out_dir / "report.json")
    except (OSError, ValueError) as error:
        print(f"FAILED  fresh {name}: no readable report ({error})")
        return None


# --- 3. negative self-check -------------------------------------------------------------------

def mutations(report):
    """(what, mutated copy, violations the schema must report as (path, keyword))."""
    cases = []

    unknown_key = copy.deepcopy(report)
    unknown_key["not_in_the_schema"] = 1
    cases.append(("unknown top-level key", unknown_key, [([], "additionalProperties")]))

    missing_key = copy.deepcopy(report)
    del missing_key["original"]
    cases.append(("required key 'original' removed", missing_key, [([], "required")]))

    # The combination the brief names: each of the two must still be reported on its own.
    both = copy.deepcopy(unknown_key)
    del both["original"]
    cases.append(("unknown key added and 'original' removed", both,
                  [([], "additionalProperties"), ([], "required")]))

    wrong_type = copy.deepcopy(report)
    wrong_type["input"]["records"] = str(wrong_type["input"]["records"])
    cases.append(("input.records as a string", wrong_type, [(["input", "records"], "type")]))

    # Closed objects deep inside too, not only at the top: a per-layer key is the likeliest
    # thing to be added to the C++ code and forgotten here.
    layers = report.get("rescheduled", {}).get("layers", [])
    if layers:
        nested = copy.deepcopy(report)
        nested["rescheduled"]["layers"][0]["not_in_the_schema"] = 1
        cases.append(("unknown key in rescheduled.layers[0]", nested,
                      [(["rescheduled", "layers", 0], "additionalProperties")]))
    return cases


def self_check(validator, report):
    """True when the valid report passes and every mutated copy fails for the expected reason."""
    if schema_errors(validator, report):
        print("FAILED  self-check: the report chosen for it does not conform itself")
        return False
    passed = True
    for what, document, expected in mutations(report):
        found = {(tuple(path), keyword) for path, keyword, _ in schema_errors(validator, document)}
        missing = [(path, keyword) for path, keyword in expected
                   if (tuple(path), keyword) not in found]
        if missing:
            print(f"FAILED  self-check: {what} was not rejected as expected "
                  f"(missing {missing}, got {sorted(found)})")
            passed = False
        else:
            print(f"ok      self-check: {what} is rejected")
    return passed


# --- coverage (information only) ---------------------------------------------------------------

def resolve(schema, node):
    while "$ref" in node:  # only local references (#/$defs/...) are used
        target = schema
        for part in node["$ref"].lstrip("#/").split("/"):
            target = target[part]
        node = target
    return node


def declared_paths(schema, node, prefix=""):
    node = resolve(schema, node)
    paths = set()
    for name, child in node.get("properties", {}).items():
        paths.add(f"{prefix}.{name}")
        paths |= declared_paths(schema, child, f"{prefix}.{name}")
    if isinstance(node.get("items"), dict):
        paths |= declared_paths(schema, node["items"], prefix + "[]")
    return paths


def written_paths(value, prefix=""):
    paths = set()
    if isinstance(value, dict):
        for name, child in value.items():
            paths.add(f"{prefix}.{name}")
            paths |= written_paths(child, f"{prefix}.{name}")
    elif isinstance(value, list):
        for child in value:
            paths |= written_paths(child, prefix + "[]")
    return paths


def print_coverage(schema, documents):
    """Keys the schema allows that no checked report wrote: optional branches the runs above do
    not reach (a null, a preset never written, ...). Not a failure; worth a look when it grows."""
    seen = set().union(*(written_paths(document) for document in documents))
    unseen = sorted(declared_paths(schema, schema) - seen)
    print(f"info    {len(unseen)} schema key(s) written by none of the checked reports"
          + (": " + ", ".join(unseen) if unseen else ""))


# --- main -------------------------------------------------------------------------------------

def main():
    arguments = parse_arguments()
    schema, validator = load_validator(arguments.schema)
    passed = True
    documents = []

    golden = golden_reports(arguments.source_dir)
    if not golden:  # a moved folder must not turn this into a test of nothing
        print("FAILED  no tests/golden/*/expect/report.json found")
        passed = False
    for path in golden:
        document = read_json(path)
        documents.append(document)
        passed &= check_document(validator, document,
                                 f"golden {path.relative_to(arguments.source_dir)}")

    folder = Path(tempfile.mkdtemp(prefix="report-schema-", dir=arguments.work_dir))
    fresh = {}
    for name, job_arguments, source in fresh_jobs(arguments.source_dir, folder):
        document = run_job(arguments.bladeaxis, name, job_arguments, source, folder)
        if document is None:
            passed = False
            continue
        fresh[name] = document
        documents.append(document)
        passed &= check_document(validator, document, f"fresh {name}")

    # The demo report is the fullest one (re-scheduled layers and CAD clearance).
    base = fresh.get("demo") or (read_json(golden[0]) if golden else None)
    if base is None:
        print("FAILED  self-check: no valid report to mutate")
        passed = False
    else:
        passed &= self_check(validator, base)

    print_coverage(schema, documents)
    print(f"summary {len(golden)} golden and {len(fresh)} fresh report(s) validated against "
          f"{arguments.schema.name}: {'all conform' if passed else 'FAILURES above'}")
    if passed:
        shutil.rmtree(folder, ignore_errors=True)
    else:
        print(f"outputs kept in {folder}")
    return 0 if passed else 1


if __name__ == "__main__":
    sys.exit(main())
