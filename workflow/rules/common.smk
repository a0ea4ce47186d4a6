# The sweep's plan, from the config (workflow/config.yaml, then --config): `opf sweep --plan`
# expands the sweep file into its runs, each with its result file, directory, settings and
# `opf run` arguments, exactly as `opf sweep` runs them.

import json
import os
import shlex
import subprocess

ROOT = os.path.dirname(workflow.basedir)


def existing_path(value):
    """A path from the config: relative to the working directory, else to the repository root."""
    value = str(value)
    if os.path.isabs(value) or os.path.exists(value):
        return os.path.abspath(value)
    return os.path.join(ROOT, value)


def scaled(key):
    """Resource `key` of the config, doubled, tripled, ... on each retry (--retries)."""
    return lambda wildcards, attempt: int(config[key]) * attempt


def plan_of_run(field):
    """A run's `field` in the plan, for the params of rule run."""
    return lambda wildcards: RUNS[wildcards.result][field]


OPF = existing_path(config.get("opf") or "build/bin/opf")
if not config.get("sweep"):
    raise ValueError("name the sweep file: --config sweep=experiments/sweeps/<name>.yaml")
_plan_command = [OPF, "sweep", existing_path(config["sweep"]), "--plan"]
if config.get("out"):
    _plan_command += ["--out", os.path.abspath(str(config["out"]))]
_planned = subprocess.run(_plan_command, capture_output=True, text=True)
if _planned.returncode != 0:
    raise ValueError(_planned.stderr.strip() or "opf sweep --plan failed")
PLAN = json.loads(_planned.stdout)
OUT = PLAN["out"]
RUNS = {run["result"]: run for run in PLAN["runs"]}
for _run in RUNS.values():
    _run["path"] = os.path.join(OUT, _run["directory"])
    _run["command"] = shlex.join([OPF] + _run["arguments"])
