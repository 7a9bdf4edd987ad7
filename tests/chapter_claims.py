"""What each executed chapter must print for its prose to hold: the sentences generated from its own numbers
(:mod:`toolkit.teaching.findings`), checked against the tables and conclusions printed beside them.

:func:`problems` reads an executed notebook (``nbformat``, with outputs) and returns what disagrees; the site's
build executes every chapter once in quick mode (``tests/test_site.py`` checks its runs with this), and
``tests/test_chapter_claims.py`` holds the checks themselves against crafted outputs.
"""

from __future__ import annotations

import re
from collections.abc import Callable

from toolkit.teaching import findings, recorded

SAMPLERS = ("BS", "OB", "G", "BT")
SENTENCE = (  # the rest of a findings.describe_accuracy sentence, its numbers and words captured
    r"(\d+)%, (above|below|level with) \"always valid\" \((\d+)%\) and (above|below|level with) a coin flip "
    r"\(50%\)( \(worse than chance\))?"
)
RATIOS = r"\| ([\d.]+) \| ([\d.]+) \| ([\d.]+) \| ([\d.]+) \|"  # a table row's four samplers' ratios


def texts(nb) -> list[str]:
    """Per code cell, everything it printed or displayed as text or Markdown, whitespace made single spaces."""
    out = []
    for cell in nb["cells"]:
        if cell["cell_type"] != "code":
            continue
        parts = []
        for output in cell.get("outputs", []):
            if output.get("output_type") == "stream":
                parts.append(output["text"])
            elif "data" in output:
                data = output["data"]
                parts.append(data.get("text/markdown", "" if "image/png" in data else data.get("text/plain", "")))
        out.append(" ".join(" ".join(parts).split()))
    return out


def prose(nb) -> str:
    """The Markdown cells, whitespace made single spaces."""
    return " ".join(" ".join("".join(c["source"]) for c in nb["cells"] if c["cell_type"] == "markdown").split())


def _percent(text: str, label: str) -> list[int]:
    return [int(v) for v in re.findall(re.escape(label) + r" \| (\d+)% \|", text)]


def chapter_02(nb) -> list[str]:
    found, problems = " ".join(texts(nb)), []
    moves = re.findall(r"z moves ([\d.]+) at 1 flip, ([\d.]+) at 30 flips: ([\d.]+)x as far", found)
    if len(moves) != 3:
        problems.append(f"02: expected one 'z moves' line per CAE (3), found {len(moves)}")
    for fewest, most, ratio in moves:
        if abs(float(most) / float(fewest) - float(ratio)) > 0.06 * float(ratio) + 0.05:
            problems.append(f"02: 'z moves {fewest} ... {most}' is not {ratio}x")
    if "least sensitive in this run:" not in found:
        problems.append("02: the least sensitive model of each panel is not printed")
    pairs = re.findall(
        r"(\d+) cells differ from the noisy input .*?: (\d+) of the 30 flips ignored, (\d+) other", found
    )
    if len(pairs) != 2 or any(int(a) != int(b) + int(c) for a, b, c in pairs):
        problems.append(f"02: the two decoders' counts are missing or do not add up: {pairs}")
    return problems


def chapter_03(nb) -> list[str]:
    found, problems = " ".join(texts(nb)), []
    for kind in ("balanced", "validity-blind"):
        always = _percent(found, f"| always valid | {kind}")
        for preset in ("paper", "strong"):
            line = re.search(rf"{preset}, {kind}: accuracy {SENTENCE}", found)
            table = _percent(found, f"| `{preset}` preset, 2DS unseen | {kind}")
            if not line or not table or not always:
                problems.append(f"03: no accuracy sentence or table row for {preset}, {kind}")
                continue
            acc, side, base, chance, worse = line.groups()
            if int(acc) != table[0] or int(base) != always[0]:
                problems.append(
                    f"03: {preset}, {kind}: the sentence says {acc}% vs {base}%, the table {table} vs {always}"
                )
            if (worse is not None) != (int(acc) < 50) or (chance == "below") != (int(acc) < 50):
                problems.append(f"03: {preset}, {kind} at {acc}%: 'worse than chance' said wrongly")
            if side != ("above" if int(acc) > int(base) else "below" if int(acc) < int(base) else "level with"):
                problems.append(f"03: {preset}, {kind}: {acc}% is not {side} {base}%")
    if "the model calls every sample valid" not in found:
        problems.append("03: the threshold sweep's sentence is not printed")
    return problems


def chapter_04(nb) -> list[str]:
    outputs, problems = texts(nb), []
    found = " ".join(outputs)
    table = {  # scenario -> this notebook's total ratios, as the comparison table printed them
        name: dict(zip(SAMPLERS, map(float, row)))
        for name, row in (
            (m.group(1), m.groups()[1:])
            for m in re.finditer(r"\| (2DS|3DC-7) \| total \| this notebook [^|]*" + RATIOS, found)
        )
    }
    for name in ("2DS", "3DC-7"):
        sentence = re.search(
            rf"{name} \(medians over \d+ quer(?:y|ies)\), total time with / without prediction "
            r"against the lazy exact planner[^:]*: prediction (.*?)\.(?: |$)",
            found,
        )
        if not sentence or name not in table:
            problems.append(f"04: no verdict sentence or table row for {name}")
            continue
        said = dict(re.findall(r"(BS|OB|G|BT) \(([\d.]+)\)", sentence.group(1)))
        for s in SAMPLERS:
            if s not in said or abs(float(said[s]) - table[name][s]) > 0.005:
                problems.append(f"04: {name} {s}: the sentence says {said.get(s)}, the table {table[name][s]}")
                continue
            verb = findings.verdict(float(said[s]))
            clause = {"saves": "saves time with", "costs": "costs time with", "ties": "ties (within 5 %) with"}[verb]
            if not re.search(re.escape(clause) + r"[^;]*\b" + s + r" \(", sentence.group(1)):
                problems.append(f"04: {name} {s} ({said[s]}) is not said to {verb}")
    lesson = next((t for t in outputs if "Where the crossover study says prediction would pay" in t), None)
    printed = next(
        (t for t in outputs if "sweeps in" not in t and re.search(r"learning (never wins|is cheaper)", t)), ""
    )
    if lesson is None:
        return problems + ["04: the lesson (findings.describe_lesson) is not displayed"]
    bullets = lesson.split("`crossover.conclusion`):")[1].split(" - ")[1:]
    if len(bullets) != 4 or any(b.strip() not in printed for b in bullets):
        problems.append("04: the lesson's crossover lines are not the printed crossover.conclusion")
    if any(f"- {name} (medians over" not in lesson for name in ("2DS", "3DC-7")):
        problems.append("04: the lesson does not repeat this run's verdicts")
    return problems


def chapter_05(nb) -> list[str]:
    found, problems = " ".join(texts(nb)), []
    against = (recorded.without("strong", "medians") or "the exact planner docs/results.md names").rstrip(".")
    documented = findings.describe_ratios(
        "3DC-7 (docs/results.md, strong preset, medians over 100 queries)",
        recorded.median_ratios("strong")["3dc7"]["total"],
        against,
    )
    if " ".join(documented.split()) not in found:
        problems.append("05: docs/results.md's 3DC-7 verdict is not printed as findings.describe_ratios says it")
    for needed in ("against the paper's Table 2: accuracy", 'accurate than answering "valid" to all of them'):
        if needed not in found:
            problems.append(f"05: '{needed}' is not printed")
    if "model disagrees" not in prose(nb):
        problems.append("05: the viewer's 'model disagrees' label is not explained")
    return problems


CHECKS: dict[str, Callable] = {"02": chapter_02, "03": chapter_03, "04": chapter_04, "05": chapter_05}


def problems(name: str, nb) -> list[str]:
    """What the executed chapter ``name`` (e.g. ``04_prm_...ipynb``) prints that disagrees with its prose's promises."""
    check = CHECKS.get(name[:2])
    return check(nb) if check else []
