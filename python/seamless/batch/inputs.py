# SPDX-License-Identifier: MIT
"""The files a batch works on: files, folders (recursively) and list files,
each with the path its outputs take under OUT_DIR (mirroring the input tree)."""

import dataclasses
import hashlib
import os
import pathlib

# Every model format seamless reads (lib/model/model.h, load_model).
MODEL_EXTENSIONS = (".json", ".bpt", ".step", ".stp", ".iges", ".igs")
# A list file: one input (file or folder) per line; blank lines and # comments skipped.
LIST_EXTENSIONS = (".txt", ".list", ".lst")


class BatchInputError(ValueError):
    """An input that does not exist, or two inputs whose outputs would collide."""


@dataclasses.dataclass(frozen=True)
class Input:
    path: str  # absolute
    relative: str  # where its outputs go under OUT_DIR, without the output extension


def _is_model(path):
    return path.suffix.lower() in MODEL_EXTENSIONS


def _folder_models(folder):
    found = []
    for root, dirs, files in os.walk(folder):
        dirs.sort()  # a deterministic order
        for name in sorted(files):
            p = pathlib.Path(root, name)
            if _is_model(p):
                found.append(Input(str(p), str(pathlib.Path(folder.name, p.relative_to(folder)))))
    return found


def _expand(arg, base):
    p = pathlib.Path(base, arg).resolve() if base else pathlib.Path(arg).resolve()
    if p.is_dir():
        return _folder_models(p)
    if not p.is_file():
        raise BatchInputError(f"{arg}: no such file or folder")
    if p.suffix.lower() in LIST_EXTENSIONS:
        found = []
        for line in p.read_text().splitlines():
            line = line.strip()
            if line and not line.startswith("#"):
                found += _expand(line, p.parent)
        return found
    return [Input(str(p), p.name)]


def collect(args):
    """Inputs of the command line's INPUTS, in order, each once."""
    inputs, seen, targets = [], set(), {}
    for arg in args:
        for item in _expand(arg, None):
            if item.path in seen:
                continue
            other = targets.get(item.relative)
            if other is not None:
                raise BatchInputError(
                    f"{item.path}: its outputs would overwrite those of {other} ({item.relative})"
                )
            seen.add(item.path)
            targets[item.relative] = item.path
            inputs.append(item)
    return inputs


def file_hash(path):
    """SHA-256 of a file's content, hex."""
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            h.update(block)
    return h.hexdigest()
