"""The numbers the findings, the README and the other documents quote are the ones their tables produce.
Each range quoted in words (e.g. "11-21 % from level 2 to level 3") is computed here again from the table
in docs/model-closures.md that it summarises, and each file that quotes it must quote that range: a
table that changes, or a file that quotes another range, fails here."""
import re

import numpy as np
import pytest


def table(text, header_start):
    """The rows (lists of cell strings) of the markdown table whose header begins with header_start."""
    lines = text.splitlines()
    start = next(i for i, line in enumerate(lines) if line.startswith(header_start))
    rows = []
    for line in lines[start + 2:]:
        if not line.startswith("|"):
            break
        rows.append([cell.strip() for cell in line.strip("|").split("|")])
    return rows


def numbers(cell):
    return [float(x) for x in re.findall(r"-?\d+(?:\.\d+)?", cell)]


def percent_range(changes):
    """'a-b' of the magnitudes in per cent, rounded as the documents write them."""
    magnitudes = sorted(abs(c) * 100 for c in changes)
    return f"{magnitudes[0]:.0f}-{magnitudes[-1]:.0f}"


@pytest.fixture(scope="module")
def docs(root):
    names = ["README.md", "docs/findings.md", "docs/model-closures.md", "docs/targets.md", "CHANGELOG.md",
             "config/converged.yaml"]
    return {name: (root / name).read_text() for name in names}


def quoted_in(docs, phrase, names):
    for name in names:
        flat = " ".join(docs[name].split())  # line breaks aside
        assert phrase in flat, f"{name} does not say '{phrase}'"


def ladder(docs):
    """{(X/X0, level): (stress at 0.05, stress at 0.10, peak force)} of the verification ladder."""
    rows = table(docs["docs/model-closures.md"], "| X/X0 | level | stress at 0.05 kPa")
    out, dryness = {}, None
    for row in rows:
        dryness = float(row[0]) if row[0] else dryness
        if row[1].isdigit():
            out[dryness, int(row[1])] = tuple(float(row[k]) for k in (2, 3, 4))
    assert len(out) == 9
    return out


def test_the_resolution_ranges_are_the_ladders(docs):
    values = ladder(docs)
    dryness = (1.0, 0.5, 0.1)
    change = lambda col, a, b: [values[x, b][col] / values[x, a][col] - 1 for x in dryness]  # noqa: E731
    at_010_2_3 = percent_range(change(1, 2, 3))
    at_010_1_3 = percent_range(change(1, 1, 3))
    force_2_3 = percent_range(change(2, 2, 3))
    assert (at_010_2_3, at_010_1_3, force_2_3) == ("11-21", "18-26", "12-15")
    quoted_in(docs, f"by {at_010_2_3} % from level 2 to level 3", ["docs/findings.md", "docs/model-closures.md",
                                                                  "config/converged.yaml"])
    quoted_in(docs, f"by {at_010_1_3} % from level 1 to level 3", ["docs/findings.md", "docs/targets.md"])
    quoted_in(docs, f"-{at_010_2_3.replace('-', ' to -')} % from level 2 to 3", ["README.md"])
    quoted_in(docs, f"peak force falls by {force_2_3} %", ["docs/findings.md"])
    # The converged stress up to strain 0.05 (level 2) and level 3's change from it.
    level_2 = ", ".join(f"{values[x, 2][0]:.1f} kPa" for x in dryness)
    assert level_2 == "105.7 kPa, 83.4 kPa, 44.1 kPa"
    quoted_in(docs, "level 2: 105.7 kPa fresh, 83.4 kPa at X/X0 = 0.5, 44.1 kPa at X/X0 = 0.1", ["docs/findings.md"])
    fresh, half, dried = (f"{100 * c:.1f} %" for c in change(0, 2, 3))
    quoted_in(docs, f"Level 3 reads {fresh}, {half} and {dried}", ["docs/findings.md"])


def test_the_bulk_modulus_ranges_are_the_k_tables(docs):
    closures = docs["docs/model-closures.md"]
    rows = table(closures, "| level | X/X0 | K = 20 MPa, adaptive")  # the convergence target's, adaptive increments
    below = {}
    for row in rows:
        at_20, water = numbers(row[2])[:2], numbers(row[-1])[:2]
        below[int(row[0]), float(row[1])] = [a / w - 1 for a, w in zip(at_20, water)]
    fresh_005 = percent_range([below[1, 1.0][0], below[2, 1.0][0]])
    fresh_010 = percent_range([below[1, 1.0][1], below[2, 1.0][1]])
    dried = tuple(f"{abs(100 * c):.0f}" for c in below[1, 0.1])
    assert (fresh_005, fresh_010, dried) == ("11-15", "32-40", ("44", "40"))
    for name in ("docs/findings.md", "docs/model-closures.md", "CHANGELOG.md"):
        quoted_in(docs, f"{fresh_005} %", [name])
        quoted_in(docs, f"{fresh_010} %", [name])
        quoted_in(docs, f"{dried[0]} % / {dried[1]} %", [name])
    quoted_in(docs, f"{fresh_005.split('-')[0]}-{dried[0]} % below water's K", ["README.md"])

    # SPH at level 1: each doubling of K from 10 to 80 MPa (the fresh cell at 0.05, which levels off, aside).
    sweep = re.search(r"K = 10 / 20 / 40 / 80 MPa\): fresh, (.*?) kPa at\s+strain 0\.05.*?and (.*?) at\s+0\.10; "
                      r"X/X0 = 0\.1, (.*?) and (.*?)\. ", closures, re.S)
    series = [numbers(group) for group in sweep.groups()]
    doublings = [b / a - 1 for s in series[1:] for a, b in zip(s, s[1:])]
    assert percent_range(doublings) == "9-34"
    quoted_in(docs, "adds 9-34 %", ["docs/findings.md", "docs/model-closures.md", "CHANGELOG.md"])


def test_the_drained_and_rate_ranges_are_their_tables(docs):
    closures = docs["docs/model-closures.md"]
    drained = [row for row in table(closures, "| X/X0 | compression L_p") if row[1] == "1e-6"]
    against = [numbers(row[3]) for row in drained]
    at_005 = percent_range([a[0] / 100 for a in against])
    at_010 = percent_range([a[1] / 100 for a in against])
    lost = sorted(numbers(row[4])[0] for row in drained)
    assert (at_005, at_010) == ("32-42", "61-68")
    quoted_in(docs, f"by {at_005} % at strain 0.05 and by {at_010} % at 0.10", ["docs/findings.md"])
    quoted_in(docs, f"{lost[0]:.1f}-{lost[-1]:.1f} % of its water", ["docs/findings.md"])

    ratios = [float(row[-1]) for row in table(closures, "| X/X0 | strain | 1 m/s")]
    above = [r - 1 for r in ratios if r > 1]
    assert percent_range(above) == "13-29" and min(ratios) == pytest.approx(0.89)
    quoted_in(docs, "13-29 % above the 0.1 m/s curve", ["docs/findings.md", "README.md"])
    quoted_in(docs, f"the 1 m/s curve reads {100 * (1 - min(ratios)):.0f} % lower", ["docs/findings.md"])


def test_the_dried_state_is_the_drying_tables(docs):
    rows = table(docs["docs/model-closures.md"], "| X/X0 | P_T0 kPa | steady at")
    at_200 = {float(row[0]): row for row in rows if row[1] == "200"}
    assert (at_200[0.5][4], at_200[0.1][4], at_200[0.1][3]) == ("0.517", "0.269", "0.229")
    quoted_in(docs, "V/V0 = 0.517 of its volume at X/X0 = 0.5 and 0.269 at X/X0 = 0.1", ["docs/findings.md"])
    quoted_in(docs, "M/M0 = 0.229 at X/X0 = 0.1", ["docs/findings.md"])
    error = max(abs(float(row[6]) - float(row[7])) / float(row[1]) for row in rows)
    assert error < 0.003  # "to 0.3 % of the turgor"
    quoted_in(docs, "reaches its target to 0.3 % of the turgor", ["docs/findings.md"])


def test_level_1_against_level_2_up_to_strain_005(docs):
    """The pressure ladder at strain 0.05: level 1's offset from level 2 (quoted for level-1 runs) and level 2's
    change from level 1 (the trust table's evidence that the steps do not shrink everywhere)."""
    values = ladder(docs)
    offsets = [values[x, 1][0] / values[x, 2][0] - 1 for x in (1.0, 0.5, 0.1)]
    changes = [values[x, 2][0] / values[x, 1][0] - 1 for x in (1.0, 0.5, 0.1)]
    assert (percent_range(offsets), percent_range(changes)) == ("0-16", "0-19")
    quoted_in(docs, "up to strain 0.05 within 0-16 % of level 2", ["docs/model-closures.md"])
    quoted_in(docs, "level 1 to 2 moved it 0-19 %", ["README.md"])
    moved = ", ".join(f"{100 * c:+.1f} %" for c in changes[:2]) + f" and {100 * changes[2]:+.1f} %"
    quoted_in(docs, f"From level 1 to 2 it moved by {moved}", ["docs/findings.md"])
    assert abs(changes[0]) < abs(values[1.0, 3][0] / values[1.0, 2][0] - 1)  # the fresh cell's step grew


def test_the_volumetric_modulus_ratio_is_its_numbers(docs):
    """eps 134-203 MPa (closed cell, level 1) against the pressure probes' 0.5-36 MPa."""
    closures = " ".join(docs["docs/model-closures.md"].split())
    eps = [float(x) for x in re.search(r"\*\*(\d+) MPa fresh, (\d+) MPa at X/X0 = 0\.5, (\d+) MPa at 0\.1\*\*",
                                       closures).groups()]
    low, high = [float(x) for x in re.search(r"measure (\d+(?:\.\d+)?)-(\d+) MPa in plant cells", closures).groups()]
    ratio = f"{min(eps) / high:.1f}-{max(eps) / low:.0f}"
    assert ratio == "3.7-406"
    quoted_in(docs, f"{ratio} times stiffer in volume", ["docs/findings.md"])
    quoted_in(docs, f"{ratio.replace('-', ' to ')} times stiffer in volume", ["docs/model-closures.md"])


def test_the_closed_cell_costs_are_one_number(docs):
    """Level 3 and level 4 of the quasi-static closed cell: the times of target convergence_fine (2026-12-08)."""
    closures = " ".join(docs["docs/model-closures.md"].split())
    level_3, level_4 = re.search(r"Level 3 took \d+ s a case \((\d\.\d) min\), level 4 \d+ s \((\d+\.\d) min\)",
                                 closures).groups()
    assert (level_3, level_4) == ("1.8", "11.0")
    quoted_in(docs, f"Level 3 takes {level_3} min a case, level 4 {level_4} min", ["docs/findings.md"])
    for name in ("docs/findings.md", "docs/model-closures.md", "README.md"):
        flat = " ".join(docs[name].split())
        assert "47 min" not in flat and "about 5 min a case" not in flat, name  # the superseded times


def trust_rows(docs):
    return table(docs["README.md"], "| quantity | strain range | configuration | status |")


def test_the_trust_table_says_what_its_tables_say(docs):
    """Every number in the README's trust table is one a finding or model-closures.md states, no row claims a
    configuration its table does not hold ('any'), and no row calls a level an upper estimate or converged where
    the steps do not shrink."""
    sources = " ".join(" ".join(docs[name].split()) for name in ("docs/findings.md", "docs/model-closures.md"))
    sources = sources.replace("−", "-")
    for row in trust_rows(docs):
        status = row[3]
        assert row[2] != "any", row
        assert "upper estimate" not in status, row
        for number in re.findall(r"-?\d+(?:\.\d+)?(?:e-?\d+)?(?: to -?\d+)?(?:-\d+(?:\.\d+)?)? ?%?", status):
            number = number.strip()
            if " to " in number:  # "-11 to -21 %": a fall the findings write as "falls by 11-21 %"
                number = number.replace("-", "").replace(" to ", "-")
            if re.fullmatch(r"\d", number) or number.startswith(("0.0", "0.1", "0.2")) and "%" not in number:
                continue  # a level (1-4) or a strain range, not a measured number
            assert number in sources, f"trust table row '{row[0]}' quotes {number!r}, which no finding states"
    energy = {row[2]: row[3] for row in trust_rows(docs) if row[0] == "energy account"}
    assert "fails" in energy["LJ coupling"] and "9.0 times the plate work" in sources


def test_the_lj_ladder_is_its_table(docs, root):
    """The LJ ladder's table of values in model-closures.md is data/numerical_band/lj_ladder.csv (what the default
    report's captions quote), and the changes findings 7 and the trust table quote are that table's."""
    import pandas as pd
    from analysis import numerical_band
    band = pd.read_csv(root / "data" / "numerical_band" / "lj_ladder.csv")
    rows = table(docs["docs/model-closures.md"], "| X/X0 | level | wall / fluid particles | dt ns |")
    assert len(rows) == len(band) == 9
    for row, (_, value) in zip(rows, band.iterrows()):
        assert (float(row[0]), int(row[1])) == (value["dryness"], value["level"])
        for cell, column, scale in ((row[4], "smoothed_stress_kPa_at_0.05", 1), (row[5], "smoothed_stress_kPa_at_0.10", 1),
                                    (row[7], "peak_force_top_uN", 1e-3)):
            assert float(cell) == pytest.approx(value[column] * scale, abs=0.051), (row, column)
    change = lambda column, low, high: [numerical_band.change(band, column, x, low, high)  # noqa: E731
                                        for x in numerical_band.DRYNESS]
    at_005, at_010 = "smoothed_stress_kPa_at_0.05", "smoothed_stress_kPa_at_0.10"
    pairs = lambda low, high: [f"{100 * a:+.0f} % / {100 * b:+.0f} %"  # noqa: E731
                               for a, b in zip(change(at_005, low, high), change(at_010, low, high))]
    one_two, two_three = pairs(1, 2), pairs(2, 3)
    quoted_in(docs, f"by {one_two[0]} at strains 0.05 / 0.10 (fresh), by {one_two[1]} at X/X0 = 0.5, and by "
                    f"{one_two[2]} at X/X0 = 0.1", ["docs/findings.md"])
    quoted_in(docs, f"it moves by {two_three[0]} (fresh), by {two_three[1]} at X/X0 = 0.5, and by {two_three[2]} at "
                    "X/X0 = 0.1", ["docs/findings.md"])
    forces = change("peak_force_top_uN", 1, 2) + change("peak_force_top_uN", 2, 3)
    assert percent_range(forces) == "18-65"
    quoted_in(docs, "The peak force moves by 18-65 % between every pair of levels", ["docs/findings.md"])
    quoted_in(docs, "the peak force by 18-65 %", ["README.md"])
    signed = lambda values: f"{100 * min(values):+.0f} to {100 * max(values):+.0f} %"  # noqa: E731 ("-3 to +10 %")
    quoted_in(docs, f"from level 1 to 2 the stress moves by {signed(change(at_005, 1, 2))} at strain 0.05 and "
                    f"{signed(change(at_010, 1, 2))} at 0.10", ["README.md"])
    quoted_in(docs, f"from level 2 to 3 by {signed(change(at_005, 2, 3))} and {signed(change(at_010, 2, 3))}",
              ["README.md"])


def test_the_readmes_times_are_the_measurements(root):
    """Every time the README's table of targets gives as measured names its date, and that time and date are in
    docs/performance.md, "How long the commands take"; no row keeps a range of superseded measurements."""
    readme = (root / "README.md").read_text()
    performance = " ".join((root / "docs" / "performance.md").read_text().split())
    rows = table(readme, "| command | what it does | time, 2 cores | disk |")
    assert len(rows) >= 15
    for command, _, time, disk in rows:
        if "measured" in time:
            dates = re.findall(r"20\d\d-\d\d-\d\d", time)
            assert dates, f"{command}: a measured time without its date"
            for stamp in dates + re.findall(r"\d+ min \d+ s", time):
                assert stamp in performance, f"{command}: {stamp} is not in docs/performance.md"
        assert disk, f"{command}: no disk use"
    sitting = re.search(r"Measured in one sitting, (20\d\d-\d\d-\d\d)", performance)
    assert sitting, "performance.md names the sitting's date"
    for command in ("`snakemake --cores 2`", "`snakemake --cores 2 --configfile config/ci.yaml`",
                    "`snakemake --cores 2 extensions`", "`scripts/test`"):
        time = next(row[2] for row in rows if row[0] == command)
        assert sitting.group(1) in time, f"{command} is not the sitting's time"
