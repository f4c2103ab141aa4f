#!/usr/bin/env python3
"""The cluster set-ups of examples/batch/ that cannot run here, checked statically.

    batch_setups.py SOURCE_DIR TMCERT_BINARY

* slurm_array.sh parses (bash -n); it is run on a real Slurm by
  tests/regression/slurm.sh.
* k8s-indexed-job.yaml parses as YAML (when PyYAML is there): an Indexed
  Job whose completions equal its SHARDS, a merge Job with the same SHARDS,
  the image that examples/batch/README.md tells to build.
* Dockerfile (no container engine here, so it is not built): its
  instructions are Dockerfile instructions, two stages, its build stage
  installs only packages that scripts/deps.sh installs, the CMake options
  and target it names exist, and its step that lists the runtime packages
  (ldd, dpkg -S) finds installed Debian packages for TMCERT_BINARY.

Ends with "N passed, M failed"; exits 1 on any failure.
"""

import re
import shlex
import subprocess
import sys
from pathlib import Path

INSTRUCTIONS = {"FROM", "RUN", "CMD", "LABEL", "EXPOSE", "ENV", "ADD", "COPY", "ENTRYPOINT", "VOLUME", "USER",
                "WORKDIR", "ARG", "ONBUILD", "STOPSIGNAL", "HEALTHCHECK", "SHELL"}


def main() -> int:
    src, tmcert = Path(sys.argv[1]), sys.argv[2]
    batch = src / "examples" / "batch"
    passed, failed = 0, 0

    def check(ok: bool, what: str) -> None:
        nonlocal passed, failed
        if ok:
            passed += 1
        else:
            failed += 1
            print(f"FAIL: {what}")

    # slurm_array.sh
    syntax = subprocess.run(["bash", "-n", str(batch / "slurm_array.sh")], capture_output=True, text=True)
    check(syntax.returncode == 0, f"slurm_array.sh: bash -n: {syntax.stderr.strip()}")

    # k8s-indexed-job.yaml
    try:
        import yaml  # Debian python3-yaml
    except ImportError:
        yaml = None
        print("note: PyYAML is not installed: k8s-indexed-job.yaml not parsed")
    readme = (batch / "README.md").read_text(encoding="utf-8")
    if yaml is not None:
        docs = list(yaml.safe_load_all((batch / "k8s-indexed-job.yaml").read_text(encoding="utf-8")))
        jobs = {d["metadata"]["name"]: d for d in docs if d}
        shards_job, merge_job = jobs.get("tmcert-batch-shards"), jobs.get("tmcert-batch-merge")
        check(shards_job is not None and merge_job is not None, "k8s-indexed-job.yaml: the two Jobs")
        if shards_job and merge_job:
            spec = shards_job["spec"]

            def env(job: dict, name: str) -> str:
                container = job["spec"]["template"]["spec"]["containers"][0]
                return next(e["value"] for e in container.get("env", []) if e["name"] == name)

            check(spec.get("completionMode") == "Indexed", "k8s: the shards' Job is Indexed")
            check(str(spec.get("completions")) == env(shards_job, "SHARDS") == env(merge_job, "SHARDS"),
                  "k8s: completions and both SHARDS agree")
            images = {c["image"] for j in (shards_job, merge_job) for c in j["spec"]["template"]["spec"]["containers"]}
            check(len(images) == 1, f"k8s: one image for both Jobs, got {images}")
            image = next(iter(images))
            check(image.split("/")[-1].split(":")[0] == "tmcert" and "Dockerfile" in readme,
                  f"k8s: the image {image} is the one examples/batch/README.md says how to build")

    # Dockerfile
    text = (batch / "Dockerfile").read_text(encoding="utf-8")
    logical, current = [], ""
    for line in text.splitlines():
        if not current and (not line.strip() or line.lstrip().startswith("#")):
            continue
        current += line.rstrip("\\").rstrip() + " " if line.endswith("\\") else line
        if not line.endswith("\\"):
            logical.append(current.strip())
            current = ""
    check(not current, "Dockerfile: a continuation line at the end")
    keywords = [entry.split()[0].upper() for entry in logical]
    unknown = sorted(set(keywords) - INSTRUCTIONS)
    check(not unknown, f"Dockerfile: unknown instructions {unknown}")
    stages = [entry for entry in logical if entry.upper().startswith("FROM ")]
    check(len(stages) == 2 and stages[0].split()[-1] == "build", "Dockerfile: a build stage and a runtime stage")
    check(any(e.startswith("COPY --from=build") for e in logical), "Dockerfile: the runtime stage copies the build")
    deps = (src / "scripts" / "deps.sh").read_text(encoding="utf-8")
    block = deps.split("packages=(", 1)[1].split("\n)", 1)[0]
    listed = {w for line in block.splitlines() for w in line.split("#", 1)[0].split()}
    build_stage = "\n".join(logical[: next(i for i, e in enumerate(logical) if i > 0 and e.startswith("FROM "))])
    installed = set()
    for match in re.finditer(r"apt-get install ([^&]*)", build_stage):
        installed |= {w for w in shlex.split(match.group(1)) if not w.startswith("-")}
    check(bool(installed) and installed <= listed,
          f"Dockerfile: build packages not in scripts/deps.sh: {sorted(installed - listed)}")
    cmake = (src / "CMakeLists.txt").read_text(encoding="utf-8")
    for option in set(re.findall(r"-D([A-Z_]+)=", text)):
        check(option.startswith("CMAKE_") or option == "BUILD_TESTING" or re.search(rf"\b{option}\b", cmake),
              f"Dockerfile: the CMake option {option} is not in CMakeLists.txt")
    for target in re.findall(r"--target (\S+)", text):
        check(f"add_executable({target}" in cmake, f"Dockerfile: no target {target}")
    # The runtime packages step, as the Dockerfile writes it, on this machine's tmcert.
    step = re.search(r"for lib in .*?done \| sort -u", build_stage, re.S)
    check(step is not None, "Dockerfile: the runtime packages step")
    if step:
        script = step.group(0).replace("/opt/tmcert/bin/tmcert", shlex.quote(tmcert))
        out = subprocess.run(["bash", "-c", script], capture_output=True, text=True)
        packages = out.stdout.split()
        state = subprocess.run(["dpkg-query", "-W", "-f=${Package} ${Status}\n"] + packages, capture_output=True,
                               text=True).stdout
        check(out.returncode == 0 and "libgmp10" in packages and
              all("install ok installed" in line for line in state.splitlines()) and len(state.splitlines()) ==
              len(packages), f"Dockerfile: runtime packages {packages}: {out.stderr.strip()}")
    print(f"{passed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
