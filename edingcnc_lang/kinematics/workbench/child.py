"""The child process of ``isolate.py``: load the compiled plug-in, record its calls, run the command.

Usage (internal): ``python -m edingcnc_lang.kinematics.workbench.child COMMAND PAYLOAD_JSON GUARD_FILE``.
Exit 0 or 1 with a JSON report on standard output; a crash is seen by the parent.
"""
from __future__ import annotations

import json
import sys


def main(argv: list[str]) -> int:
    from edingcnc_lang.errors import EcncError
    from edingcnc_lang.kinematics.workbench import check, compare
    from edingcnc_lang.kinematics.workbench.findings import KinsFinding
    from edingcnc_lang.kinematics.workbench.isolate import guard_calls

    command, payload, guard = argv[0], json.loads(argv[1]), argv[2]
    options = check.options_from_json(payload["options"])
    machine = check.read_machine(options.ini)

    def loaded(name: str):
        kins = check.load_plugin(name, machine)
        if hasattr(kins, "_fn"):
            guard_calls(kins, guard)
        return kins

    if command == "check":
        try:
            kins = loaded(payload["name"])
        except EcncError as err:
            report = check._crash_report(payload["name"], options)
            report.findings.append(KinsFinding("K601", err.message))
        else:
            report = check.check_loaded(kins, payload["name"], options, machine)
        print(json.dumps(report.to_json()))
        return 0 if report.ok else 1
    try:
        a, b = loaded(payload["a"]), loaded(payload["b"])
    except EcncError as err:
        print(json.dumps({"error": err.message}))
        return 2
    result = compare.compare_loaded(a, b, payload["a"], payload["b"], options, machine)
    print(json.dumps(result.to_json()))
    return 0 if result.ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
