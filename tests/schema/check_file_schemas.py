#!/usr/bin/env python3
"""Job and machine files against their JSON Schemas (resources/schemas/, draft 2020-12).

What each part proves:
- every object of both schemas is closed (additionalProperties: false), so the schemas refuse an
  unknown key as the readers do (the readers take their key lists from these schemas);
- the machine files BladeAxis ships and the test data's machine files are valid, and so are the
  job files kept for the fuzzer that the reader accepts and the examples in the docs;
- documentation and schema agree: every key of a schema is in its page's tables
  (docs/job-file.md, docs/machine-file.md), and every key a table names is in the schema;
- the schemas can fail: a misspelt key and a value of the wrong type are each refused.
"""

import argparse
import copy
import json
import pathlib
import re
import sys

from jsonschema import Draft202012Validator


def load(path):
    with open(path, encoding="utf-8") as file:
        return json.load(file)


def objects_of(schema, where="$"):
    """Every object schema inside `schema`, with where it is."""
    if isinstance(schema, dict):
        if schema.get("type") == "object":
            yield where, schema
        for key, value in schema.items():
            yield from objects_of(value, f"{where}.{key}")
    elif isinstance(schema, list):
        for index, value in enumerate(schema):
            yield from objects_of(value, f"{where}[{index}]")


def property_names(schema):
    names = set()
    for _, obj in objects_of(schema):
        names.update(obj.get("properties", {}).keys())
    return names


def documented_keys(page):
    """The backticked keys in the first column of the page's key tables (header "| key")."""
    keys = set()
    in_key_table = False
    for line in page.read_text(encoding="utf-8").splitlines():
        if not line.startswith("|"):
            in_key_table = False
            continue
        first = line.split("|")[1].strip()
        if first.startswith("key"):
            in_key_table = True
        elif in_key_table:
            keys.update(re.findall(r"`([a-z][a-z0-9_]*)`", first))
    return keys


def json_blocks(page):
    """The ```json blocks of a page that are whole documents."""
    blocks = re.findall(r"```json\n(.*?)```", page.read_text(encoding="utf-8"), re.S)
    for block in blocks:
        try:
            yield json.loads(block)
        except json.JSONDecodeError:
            continue  # a fragment such as a "layer_edits": [...] excerpt


class Checker:
    def __init__(self):
        self.failures = []

    def expect(self, condition, message):
        if not condition:
            self.failures.append(message)

    def valid(self, validator, document, name):
        errors = sorted(validator.iter_errors(document), key=lambda e: list(e.path))
        self.expect(not errors, f"{name}: " + "; ".join(e.message for e in errors[:3]))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--source-dir", required=True, type=pathlib.Path)
    args = parser.parse_args()
    root = args.source_dir
    check = Checker()
    schemas = {
        "job": load(root / "resources/schemas/job-file.schema.json"),
        "machine": load(root / "resources/schemas/machine-file.schema.json"),
    }
    validators = {}
    for name, schema in schemas.items():
        Draft202012Validator.check_schema(schema)
        validators[name] = Draft202012Validator(schema)
        for where, obj in objects_of(schema):
            check.expect(obj.get("additionalProperties") is False,
                         f"{name} schema {where}: an object that is not closed")

    machines = sorted((root / "resources/machines").glob("*.json"))
    machines += sorted((root / "tests/data/machines").glob("*.json"))
    check.expect(len(machines) >= 4, "no machine files found")
    for path in machines:
        check.valid(validators["machine"], load(path), str(path.relative_to(root)))
    for path in ["full_job.json", "demo.json"]:
        job = root / "tests/fuzz/corpus/job_file" / path
        check.valid(validators["job"], load(job), str(job.relative_to(root)))
    for page, name in [("docs/job-file.md", "job"), ("docs/machine-file.md", "machine")]:
        for index, block in enumerate(json_blocks(root / page)):
            if block.get("schema", "").startswith("bladeaxis-" + name):
                check.valid(validators[name], block, f"{page} example {index + 1}")
        in_schema = property_names(schemas[name]) - {"schema"}
        # Axis letters are the axes object's properties; the page names them in prose.
        in_schema -= {"X", "Y", "Z", "A", "B"}
        in_page = documented_keys(root / page)
        for key in sorted(in_schema - in_page):
            check.expect(False, f"{page}: the schema's key {key} is not documented")
        for key in sorted(in_page - property_names(schemas[name])):
            check.expect(False, f"{page}: documents {key}, which the schema does not have")

    # The schemas can fail: a misspelt key and a wrong type are refused.
    job = load(root / "tests/fuzz/corpus/job_file/full_job.json")
    misspelt = copy.deepcopy(job)
    misspelt["output_programm"] = misspelt.pop("output_program")
    check.expect(not validators["job"].is_valid(misspelt), "a misspelt job key was accepted")
    wrong = copy.deepcopy(job)
    wrong["parameters"]["margin_deg"] = "three"
    check.expect(not validators["job"].is_valid(wrong), "a parameter as text was accepted")
    machine = load(root / "resources/machines/blade_ab.json")
    machine["axes"]["Z"]["max_mmm"] = 1
    check.expect(not validators["machine"].is_valid(machine), "a misspelt axis key was accepted")

    for failure in check.failures:
        print("FAIL:", failure)
    print(f"{len(check.failures)} failure(s)")
    return 1 if check.failures else 0


if __name__ == "__main__":
    sys.exit(main())
