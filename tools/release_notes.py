"""Print the section of CHANGELOG.md for one version: the release notes of its tag.

Usage: ``python tools/release_notes.py v0.1.0 [CHANGELOG.md]`` (a leading ``v`` is dropped).
Exits with an error naming the version when the changelog has no section for it, so that a
tag without notes fails the release job instead of publishing empty notes.
"""

from __future__ import annotations

import re
import sys
from pathlib import Path


def section(changelog: str, version: str) -> str:
    """Return the body of the ``## [version]`` section of a Keep a Changelog text.

    Raises
    ------
    ValueError
        If there is no such section, or it is empty.
    """
    version = version.removeprefix("refs/tags/").removeprefix("v")
    heading = re.compile(rf"^## \[{re.escape(version)}\]", re.MULTILINE)
    match = heading.search(changelog)
    if match is None:
        raise ValueError(f"CHANGELOG.md has no section '## [{version}]'")
    start = (
        changelog.index("\n", match.end()) + 1
        if "\n" in changelog[match.end() :]
        else len(changelog)
    )
    following = re.compile(r"^## \[", re.MULTILINE).search(changelog, start)
    body = changelog[start : following.start() if following else len(changelog)].strip()
    if not body:
        raise ValueError(f"the section '## [{version}]' of CHANGELOG.md is empty")
    return body + "\n"


def main(argv: list[str]) -> int:
    if len(argv) not in (2, 3):
        sys.exit(__doc__)
    path = Path(argv[2] if len(argv) == 3 else Path(__file__).resolve().parents[1] / "CHANGELOG.md")
    try:
        sys.stdout.write(section(path.read_text(encoding="utf-8"), argv[1]))
    except ValueError as err:
        sys.exit(f"release notes: {err}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv))
