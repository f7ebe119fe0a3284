"""The robustness sweep of issue 23 through the real quasidev command: a generated family
(scripts/mesh_family.py; five bases × bump amplitudes and widths × vertex jitter, fixed seed),
each member run with every developability term and with auto from the same input.

What must hold on every member: auto keeps (within 2 percentage points of G_ABD removed) what
the best single term gives, but for at most one member in 30, and never loses more than 5
points; no term folds a face. On the smooth members of the developable bases (plane, cylinder,
cone) with bumps up to 1 AE, auto removes at least 90 %; on irregular triangulations of the
smooth cylinders and cones with bumps 0.16 wide, at least 95 % on all but one member in eight. On
bumps of 4 AE it keeps the best term on every member. On 60 members of another seed, at
amplitudes, widths and a jitter outside the grid, it keeps the best term on every one.
docs/robustness.md gives the whole table,
including the members where the 90 % is not reached (the tangent developable)."""
import json
import os
import subprocess
import sys

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import mesh_family  # noqa: E402
import robustness_sweep as rs  # noqa: E402

BUILD = os.environ.get("QD_BUILD_DIR", os.path.join(ROOT, "build"))
QUASIDEV = os.path.join(BUILD, "bin", "quasidev")
TERMS = ("curve", "defect", "both", "auto")
MEMBERS = [mesh_family.Member(b, a, w, j, 1, 1) for b in mesh_family.BASES for a in (0.5, 1, 2)
           for w in (0.08, 0.16) for j in (0, 0.05, 0.2)]


@pytest.fixture(scope="module")
def rows():
    return sweep(MEMBERS)


def sweep(members):
    """Every member run with every term and with auto."""
    return rs.sweep(members, TERMS, QUASIDEV, jobs=2)


def gap(row):
    """Best single term's reduction minus auto's, percentage points."""
    singles = [row[t]["reduction"] for t in ("curve", "defect", "both") if "error" not in row[t]]
    return max(singles) - row["auto"]["reduction"]


def assert_auto_keeps_the_best_term(rows):
    """Auto is within 2 points of the best single term on every member."""
    gaps = {row["member"]: round(gap(row), 1) for row in rows}
    assert max(gaps.values()) <= 2.0, gaps


def assert_auto_ran(rows):
    assert all("error" not in row["auto"] for row in rows), [r["member"] for r in rows if "error" in r["auto"]]


def assert_no_term_folds_a_face(rows):
    folded = [(row["member"], t) for row in rows for t in TERMS
              if "error" not in row[t] and row[t]["flipped"] > 0]
    assert not folded


def assert_smooth_bumps_on_developable_bases_go(rows, largest, members):
    """Auto removes at least 90 % on the smooth members of the plane, cylinder and cone with
    bumps up to `largest` AE (`members` of them)."""
    smooth = [row for row in rows if row["smooth"] and row["base"] in ("plane", "cylinder", "cone")
              and row["amplitude"] <= largest]
    assert len(smooth) == members
    low = [(row["member"], round(row["auto"]["reduction"], 1)) for row in smooth
           if row["auto"]["reduction"] < 90.0]
    assert not low


def test_auto_keeps_what_the_best_term_gives(rows):
    assert_auto_ran(rows)
    gaps = {row["member"]: gap(row) for row in rows}
    assert max(gaps.values()) <= 5.0, max(gaps.items(), key=lambda kv: kv[1])
    missed = [m for m, g in gaps.items() if g > 2.0]
    assert len(missed) <= len(rows) // 30, missed


def test_no_term_folds_a_face(rows):
    assert_no_term_folds_a_face(rows)


def test_smooth_bumps_on_developable_bases_go(rows):
    assert_smooth_bumps_on_developable_bases_go(rows, 1, 3 * 2 * 2)


LARGE_BUMPS = [mesh_family.Member(b, 4, w, 0, 1, 1) for b in mesh_family.BASES for w in (0.08, 0.16)]


def test_a_slow_starter_is_not_dropped_behind_a_lead_that_has_stopped():
    """Bumps of 4 AE: here one term often stops within a few iterations (a refused step, a
    plateau) while another starts slowly and removes more later. The race treats a stopped
    leader as final and lets the others run on, so auto keeps the best term on every member."""
    rows = sweep(LARGE_BUMPS)
    assert_auto_keeps_the_best_term(rows)


def test_a_term_that_takes_hold_late_is_not_stopped_at_the_keep_leader_round():
    """The cylinder with bumps of 2 AE, 0.16 wide: both's re-fitted targets take hold after round
    12, where the race keeps only the leader (defect), and both ends 8 points ahead. The race
    lets a term run on whose pace over its last iterations would take it below the leader by
    the last iteration (term_race.h), so auto keeps both."""
    member = mesh_family.Member("cylinder", 2, 0.16, 0, 1, 1)
    row = sweep([member])[0]
    assert gap(row) <= 2.0, row
    assert row["auto"]["chosen"] == "both", row["auto"]
    assert row["auto"]["iterations"] > 0.4 * 30, row["auto"]


def test_the_race_fits_the_curve_again_rather_than_drop_it():
    """The plane with bumps of 4 AE, 0.16 wide: the curve term's first targets raise G_ABD, and
    the race would drop it at round 3, far behind the angle-defect rows (71 % in the end). Fitted
    again instead (term_race.h), the curve term removes nearly all; the stop reason says so."""
    member = mesh_family.Member("plane", 4, 0.16, 0, 1, 1)
    row = rs.sweep([member], ("defect", "auto"), QUASIDEV, jobs=1)[0]
    assert row["auto"]["chosen"] == "curve", row["auto"]
    assert "where its re-projected targets had fallen far behind another term's" in row["auto"]["stop"]
    assert row["auto"]["reduction"] >= 90.0 and row["defect"]["reduction"] < 80.0, row


def test_a_term_dropped_at_the_trial_rejoins_when_the_leader_stops_short():
    """The tangent developable with bumps of 1 AE, 0.16 wide, and the lampshade with bumps of
    2 AE, 0.08 wide (12k faces each): the term that removes most trails at round 3 and is
    dropped; the leader then stops by its own rule well before maxIter. The dropped term, whose
    pace would still take it below the leader, rejoins and finishes (term_race.h), so auto keeps
    it (it lost 5 points on each before)."""
    members = [mesh_family.Member("tangent", 1, 0.16, 0, 2, 1),
               mesh_family.Member("lampshade", 2, 0.08, 0, 2, 1)]
    rows = sweep(members)
    assert_auto_keeps_the_best_term(rows)


IRREGULAR = [mesh_family.Member(b, a, 0.16, 0, 1, 1, i) for b in ("cylinder", "cone") for a in (0.5, 1)
             for i in (0.1, 0.24)]


def test_irregular_triangles_on_smooth_bases_lose_their_bumps_without_moving_further():
    """The smooth cylinders and cones with bumps 0.16 wide, triangulated irregularly: each interior
    vertex slid within the surface by up to 0.1 or 0.24 of a cell and every cell split along a
    random diagonal (mesh_family.py `irregular`). No edge then follows a ruling, so no face normal
    can reach the curve targets; before auto tried the stronger angle-defect rows after its pick
    (group_run.h) it removed 76–93 % of G_ABD here. Those rows, kept only where they leave less and
    move no vertex further, remove at least 95 % on all but one member in eight, and auto never
    moves further on average than the curve term or both."""
    rows = sweep(IRREGULAR)
    assert all("error" not in row[t] for row in rows for t in TERMS)
    low = [(row["member"], round(row["auto"]["reduction"], 1)) for row in rows
           if row["auto"]["reduction"] < 95.0]
    assert len(low) <= len(rows) // 8, low
    assert_auto_keeps_the_best_term(rows)
    further = [row["member"] for row in rows
               if row["auto"]["mean_move_ae"] > min(row["curve"]["mean_move_ae"], row["both"]["mean_move_ae"])]
    assert not further, further


def test_creeping_rows_get_a_stronger_pull_within_a_curve_candidates_move():
    """The smooth tangent developable of seed 2 with bumps of 0.75 AE, 0.12 wide (3k faces, a
    member of the held-out family that no rule was measured on): the race picks the angle-defect
    rows, which creep to a plateau at 84 %, while the curve term and both, which moved further,
    remove less. The rows at stronger weights then run too, bounded by the move of the
    candidate with curve targets that moved most, and are kept where they leave at most half of
    what the pick left (group_run.h): auto removes at least 90 %, and moves no further on average
    than the curve term or both run alone."""
    member = mesh_family.Member("tangent", 0.75, 0.12, 0, 1, 2)
    row = sweep([member])[0]
    assert row["defect"]["reduction"] < 90.0 and row["auto"]["reduction"] >= 90.0, row
    assert row["auto"]["chosen"].startswith("defect ×"), row["auto"]
    assert row["auto"]["reduction"] >= 100 - 0.5 * (100 - row["defect"]["reduction"]), row
    assert row["auto"]["mean_move_ae"] <= max(row["curve"]["mean_move_ae"], row["both"]["mean_move_ae"]), row


def test_rows_stopped_at_their_plateau_get_a_stronger_pull_within_the_tolerance():
    """The irregular tangent developable with bumps of 1 AE, 0.16 wide (3k faces, cells slid by up
    to 0.1): the race picks the angle-defect rows, which stop at their plateau with 61 % removed,
    while the curve term's and both's steps remove nothing, so neither moved further and none
    bounded the stronger rows, which were not tried. Where the pick stopped at its plateau before
    maxIter, the stronger rows now run bounded by the tolerance alone and are kept where they leave
    at most half of what the pick left (group_run.h): auto removes at least 90 %, folding no face."""
    member = mesh_family.Member("tangent", 1, 0.16, 0, 1, 1, 0.1)
    row = rs.sweep([member], ("defect", "auto"), QUASIDEV, jobs=1)[0]
    assert row["defect"]["reduction"] < 90.0 and row["auto"]["reduction"] >= 90.0, row
    assert row["auto"]["chosen"].startswith("defect ×"), row["auto"]
    assert row["auto"]["bounded_by"] == "tolerance", row["auto"]
    assert row["auto"]["reduction"] >= 100 - 0.5 * (100 - row["defect"]["reduction"]), row
    assert row["auto"]["flipped"] == 0, row["auto"]


def candidates(member, tmp_path):
    """Auto's candidates on the member, from its report."""
    mesh, report = tmp_path / f"{member.name}.ply", tmp_path / f"{member.name}.json"
    mesh_family.write_ply(str(mesh), *mesh_family.make(member))
    subprocess.run([QUASIDEV, "approximate", str(mesh), str(tmp_path / "out.ply"), "--quiet",
                    "--report", str(report)], check=True)
    return json.loads(report.read_text())["patches"][0]["candidates"]


def assert_auto_keeps_both(members, tmp_path):
    """Auto is within 2 points of the best term on every member, and its race keeps both (which
    the stronger rows may then beat: group_run.h)."""
    rows = sweep(members)
    assert_auto_keeps_the_best_term(rows)
    for member in members:
        cands = candidates(member, tmp_path)
        kept = next(c for c in cands if c["kept"])
        raced = [c for c in cands if c["defect_weight_factor"] == 1 and c["started"]]
        best = max(raced, key=lambda c: c["abd_reduction"])
        assert best["term"] == "both", (member.name, cands)
        assert kept is best or kept["defect_weight_factor"] != 1, (member.name, cands)


def test_both_starts_late_where_the_rows_stop_short(tmp_path):
    """An irregular cone with bumps of 2 AE, 0.08 wide, and an irregular lampshade likewise
    (3k faces each): the curve term's first step removes nothing and the angle-defect rows' some,
    so both, the rows with the curve targets, does not start with them (its first steps cost the
    garments' panels time for nothing, term_race.h). The rows then stop by their own rule at 61 %
    and 60 %, where both alone reaches 74 % and 67 %. Both now starts when the rows stop, from the
    same start, and auto keeps it (it lost 13 and 7 points before)."""
    members = [mesh_family.Member("cone", 2, 0.08, 0, 1, 1, 0.24),
               mesh_family.Member("lampshade", 2, 0.08, 0, 1, 1, 0.1)]
    assert_auto_keeps_both(members, tmp_path)


def test_auto_costs_what_the_curve_term_does_where_its_pace_leaves_little():
    """The irregular plane with bumps of 1 AE, 0.16 wide (12k faces): the curve term's first step
    leaves 1.5 % of G_ABD, more than δ_ABD, so the other terms started and cost auto three times
    the curve term's run. At that step's pace its second leaves less than δ_ABD, so the race now
    takes that step alone too (term_race.h); it does leave less, the others never start, and auto
    is the curve term's own run: the same factorisations and G_ABD removed."""
    member = mesh_family.Member("plane", 1, 0.16, 0, 2, 1, 0.1)
    row = rs.sweep([member], ("curve", "auto"), QUASIDEV, jobs=2)[0]
    assert row["auto"]["chosen"] == "curve", row["auto"]
    assert row["auto"]["factorizations"] == row["curve"]["factorizations"], row
    assert abs(row["auto"]["reduction"] - row["curve"]["reduction"]) < 0.01, row


def test_a_rejoining_term_is_judged_by_its_steps_after_it_rejoins(tmp_path):
    """The irregular cylinder with bumps of 2 AE, 0.08 wide, and the irregular lampshade with bumps
    of 1 AE, 0.08 wide (3k faces each, cells slid by up to 0.24): both, the rows with the curve
    targets, is dropped by the trial, and the leader then stops by its own rule short of maxIter.
    Judged by its pace where it was dropped, both did not rejoin, and auto lost 10 and 6 points to
    it. It now rejoins, is judged by the steps it takes from there (term_race.h), and auto keeps
    it."""
    members = [mesh_family.Member("cylinder", 2, 0.08, 0, 1, 1, 0.24),
               mesh_family.Member("lampshade", 1, 0.08, 0, 1, 1, 0.24)]
    assert_auto_keeps_both(members, tmp_path)


def test_a_pace_is_judged_within_one_phase_of_a_run(tmp_path):
    """The lampshade with bumps of 2 AE, 0.16 wide (12k faces): both's targets are re-fitted after
    its 13th iteration and its anchors move after its 16th, and the steps between raise G_ABD. Judged
    by its pace over those steps, both was dropped, and auto kept the curve term's 89 % where both
    alone reaches 97 %. A pace is now judged only within one phase of a run (term_race.h), as the
    plateau rule judges it, and auto keeps both."""
    assert_auto_keeps_both([mesh_family.Member("lampshade", 2, 0.16, 0, 2, 1)], tmp_path)


def test_a_trailer_on_a_shortened_step_is_not_dropped_for_its_rank(tmp_path):
    """The cone with bumps of 2 AE, 0.16 wide (3k faces): at round 3, a tenth of maxIter, both
    trails (57 % against the curve term's 65 %) because the never-worse rule has halved its step;
    it backs off its weights at iteration 7 and ends at 93 %, where the curve term ends at 89 %.
    Dropped for its rank at round 3, it left auto 3.7 points behind. A trailer whose last step was
    shortened is not dropped for its rank (term_race.h), and auto keeps both."""
    assert_auto_keeps_both([mesh_family.Member("cone", 2, 0.16, 0, 1, 1)], tmp_path)


def test_a_trailer_on_a_step_at_weaker_weights_is_not_dropped_for_its_rank():
    """The smooth lampshade with bumps of 1.8 AE, 0.1 wide, of seed 5 (3k faces): at round 3 the
    curve term trails because its full step folded faces and the never-worse rule solved it again
    with its weights at a ninth. The race re-fitted its curve instead of dropping it, and the
    re-fitted targets stalled at 77 %; run alone, its re-projected targets reach 79 %. A step
    solved again at weaker weights is a refused full step, as a shortened one is (term_race.h),
    so the curve term is not judged by its rank there, and auto keeps what it gives alone."""
    member = mesh_family.Member("lampshade", 1.8, 0.1, 0, 1, 5)
    row = rs.sweep([member], ("curve", "auto"), QUASIDEV, jobs=1)[0]
    assert row["auto"]["chosen"] == "curve", row["auto"]
    assert "fallen far behind" not in row["auto"]["stop"], row["auto"]
    assert row["auto"]["reduction"] >= row["curve"]["reduction"] - 0.5, row


def test_a_rejoined_term_is_fitted_again_rather_than_dropped_by_its_pace(tmp_path):
    """The irregular cylinder with bumps of 2 AE, 0.08 wide (3k faces, cells slid by up to 0.1):
    the curve term stops at a plateau at iteration 27 with 86 %; both, dropped at the keep-leader
    round, rejoins, and its pace over its next steps (its targets stalling) would not take it
    below the leader, so it was dropped at 84 %. Alone, its stop rule fits its curve again at
    that stall and it ends at 89 %. A rejoined candidate with curve targets is now fitted again
    instead of dropped (term_race.h), and auto keeps both."""
    assert_auto_keeps_both([mesh_family.Member("cylinder", 2, 0.08, 0, 1, 1, 0.1)], tmp_path)


# Members no rule was tuned on: another seed (other bump centres and jitter), and amplitudes,
# widths and a jitter that the sweep's grid (and every member named above) does not hold.
HELD_OUT = [mesh_family.Member(b, a, w, j, 1, 2) for b in mesh_family.BASES for a in (0.75, 1.5, 3)
            for w in (0.12, 0.2) for j in (0, 0.1)]


def test_auto_keeps_the_best_term_on_members_nobody_tuned_on():
    """60 members of seed 2 at amplitudes, widths and a jitter outside the grid: auto keeps what
    the best single term gives on every one, with no allowance (on the 120 members of
    docs/heldout/robustness_sweep.md, 12k-face ones too, it lost at most 0.6 point); no term
    folds a face; the smooth bumps of up to 1.5 AE on the developable bases go."""
    rows = sweep(HELD_OUT)
    assert_auto_ran(rows)
    assert_auto_keeps_the_best_term(rows)
    assert_no_term_folds_a_face(rows)
    assert_smooth_bumps_on_developable_bases_go(rows, 1.5, 3 * 2 * 2)


def test_stronger_rows_stopped_by_their_bound_keep_their_best_iterate_within_it():
    """The smooth lampshade with bumps of 0.3 AE, 0.1 wide, cells slid by up to 0.15 (3k faces,
    seed 3: a family no rule was measured on): the race picks both, whose first step moves a
    vertex by the whole tolerance and removes 62 %, after which every step raises G_ABD. The
    stronger angle-defect rows then leave 24 % after one iteration, within the pick's move, and
    8 % after two, a little beyond it, where they stop. Judged by that last iterate they were not
    kept; they are now judged by their best iterate within the bound (group_run.h), which
    dominates the pick, and auto keeps it: at least 70 %, no vertex moved further than both run
    alone moved one, and the stop reason names the bound."""
    member = mesh_family.Member("lampshade", 0.3, 0.1, 0, 1, 3, 0.15)
    row = rs.sweep([member], ("both", "auto"), QUASIDEV, jobs=1)[0]
    assert row["both"]["reduction"] < 65.0 and row["auto"]["reduction"] >= 70.0, row
    assert row["auto"]["chosen"].startswith("defect ×"), row["auto"]
    assert row["auto"]["max_move_ae"] <= row["both"]["max_move_ae"], row
    assert row["auto"]["stop"].startswith("move bound"), row["auto"]
    assert row["auto"]["flipped"] == 0, row["auto"]


def test_the_stronger_rows_keep_the_weight_that_goes_furthest_within_their_bound(tmp_path):
    """The smooth tangent developable with bumps of 0.5 AE, 0.16 wide (3k faces): the race picks
    the curve term, 59 %, after which every step raises G_ABD. The angle-defect rows at a hundred
    times the weight move further than that pick within a few iterations and remove less; at a
    tenth and a third of that pull they go on within its move. Auto runs every stronger weight
    against the same bar and keeps the one that leaves least (group_run.h): at least 90 %, no
    vertex moved further than the curve term run alone moved one, and the log names each weight
    and why it was or was not kept (a weight after the kept one stops once its pace would not
    beat it)."""
    member = mesh_family.Member("tangent", 0.5, 0.16, 0, 1, 1)
    row = rs.sweep([member], ("curve", "auto"), QUASIDEV, jobs=1)[0]
    assert row["curve"]["reduction"] < 70.0 and row["auto"]["reduction"] >= 90.0, row
    assert row["auto"]["chosen"] in ("defect ×30", "defect ×10"), row["auto"]
    assert row["auto"]["max_move_ae"] <= row["curve"]["max_move_ae"], row
    assert row["auto"]["flipped"] == 0, row["auto"]
    mesh, report = tmp_path / "tangent.ply", tmp_path / "r.json"
    mesh_family.write_ply(str(mesh), *mesh_family.make(member))
    r = subprocess.run([QUASIDEV, "approximate", str(mesh), str(tmp_path / "out.ply"), "--report",
                        str(report)], capture_output=True, text=True, check=True)
    stronger = [c for c in json.loads(report.read_text())["patches"][0]["candidates"]
                if c["defect_weight_factor"] != 1]
    assert sorted(c["defect_weight_factor"] for c in stronger) == [10, 30, 100], stronger
    kept = [c for c in stronger if c["kept"]]
    assert len(kept) == 1 and all(c["abd_reduction"] <= kept[0]["abd_reduction"] for c in stronger)
    assert "defect ×100 weight" in r.stdout and "(stopped: moved further than the pick)" in r.stdout
    outdone = [c for c in stronger if c["outdone_by_weight_factor"] is not None]
    assert outdone, stronger
    for c in outdone:
        why = ("(stopped: its pace would not beat" if c["outpaced"] else "(passed, but")
        assert f"{why} defect ×{c['outdone_by_weight_factor']:g} weight" in r.stdout, r.stdout
