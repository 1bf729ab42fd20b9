"""evaluate on the shared characters. The figures measured are asserted a little below, so that a
regression fails; the issue's goals (NN 0.9, mAP 0.75, ROC-AUC 0.9) are not all reached."""

import re

from conftest import matches_all, succeeds

# Walk, run and idle of the Fox and the Knight: 11 clips, read from two .glb files.
ELEVEN_CLIPS = ["Knight.glb,Walking_A,walk,kaykit", "Knight.glb,Walking_B,walk,kaykit",
                "Knight.glb,Walking_C,walk,kaykit", "Knight.glb,Running_A,run,kaykit",
                "Knight.glb,Running_B,run,kaykit", "Knight.glb,Idle,idle,kaykit", "Knight.glb,Unarmed_Idle,idle,kaykit",
                "Knight.glb,2H_Melee_Idle,idle,kaykit", "Fox.glb,Walk,walk,fox", "Fox.glb,Run,run,fox",
                "Fox.glb,Survey,idle,fox"]
FIRST_CLASSES = re.compile(r"^[^,]+,[^,]*,(walk|run|idle|jump|death)(,|$)")


# By the default policy (motion signatures) 8 of 11 nearest neighbours are right (by strain
# histograms, the default before, 5 of 11): every idle, one run of three, three walks of four.
def test_evaluate_characters(tool, scratch, characters, motions):
    labels = scratch / "characters.csv"
    labels.write_text("file,clip,motion,rig\n" + "".join(f"{characters}/{row}\n" for row in ELEVEN_CLIPS))
    matches_all(succeeds(tool("evaluate", labels, "--fps", "30")).output,
                r"reading 8 clip\(s\) of [^\n]*Knight.glb", r"reading 3 clip\(s\) of [^\n]*Fox.glb",
                r"items +11\n", r"queries +11\n", r"NN accuracy +0.727\n", r"mAP +0.819\n", r"ROC-AUC +0.781\n",
                r"idle +4 / 4", r"run +1 / 3", r"walk +3 / 4")


# The classes issue 13 first measured (walk, run, idle, jump, death; the one dance is a
# distractor of motions.csv), the other clips left out: 68 clips of all seven bodies. By the default
# policy NN 0.853, mAP 0.802, ROC-AUC 0.915, medians 0.762 same / 0.469 different (by strain
# histograms, the default before, 0.412, 0.452, 0.652); the nearest-neighbour goal of 0.9 is not
# reached (KayKit's Running_B is taken for a walk).
def test_evaluate_first_classes(tool, scratch, characters, motions):
    rows = [row for row in motions.read_text().splitlines() if FIRST_CLASSES.match(row)]
    labels = scratch / "first_classes.csv"
    labels.write_text("file,clip,motion,rig\n" + "".join(f"{characters}/{row}\n" for row in rows))
    matches_all(succeeds(tool("evaluate", labels)).output,
                r"items +68\n", r"queries +68\n", r"NN accuracy +(0\.(8[3-9]|9[0-9])[0-9]|1\.000)\n",
                r"mAP +0\.(7[8-9]|[89][0-9])[0-9]\n", r"ROC-AUC +(0\.9[0-9][0-9]|1\.000)\n",
                r"median same +0\.(7[4-9]|[89][0-9])[0-9] ", r"median different +0\.([0-3][0-9]|4[0-8])[0-9] ")


# The whole shared evaluation by the self-similarity policy: measured NN 0.333, mAP 0.293,
# ROC-AUC 0.713, medians 0.518 same / 0.343 different.
def test_evaluate_all_characters_self_similarity(tool, motions):
    matches_all(succeeds(tool("evaluate", motions, "--policy", "self-similarity")).output,
                r"items +362\n", r"queries +306\n", r"NN accuracy +0\.(3[1-9]|[4-9][0-9])[0-9]\n",
                r"mAP +0\.(2[7-9]|[3-9][0-9])[0-9]\n", r"ROC-AUC +0\.(69|[7-9][0-9])[0-9]\n",
                r"median different +0\.3[0-6][0-9] ")


# A file's clips are read in parallel and kept or skipped in their order: the same report on 1 and
# 2 threads, two missing clips skipped in order; without --skip-unreadable the first is named.
def test_evaluate_reads_clips_in_parallel(tool, scratch, characters, motions):
    rows = ELEVEN_CLIPS[:3] + ["Knight.glb,No_such_clip_A,walk,kaykit"] + ELEVEN_CLIPS[3:]
    rows += ["Knight.glb,No_such_clip_B,idle,kaykit"]
    labels = scratch / "parallel.csv"
    labels.write_text("file,clip,motion,rig\n" + "".join(f"{characters}/{row}\n" for row in rows))
    reports = [succeeds(tool("evaluate", labels, "--skip-unreadable", "--threads", n, "--json", "-")).json()
               for n in ("1", "2")]
    for report in reports:
        report.pop("seconds")
    assert reports[0] == reports[1]
    assert len(reports[0]["inputs"]) == 11 and len(reports[0]["skipped"]) == 2
    assert "No_such_clip_A" in reports[0]["skipped"][0] and "No_such_clip_B" in reports[0]["skipped"][1]
    run = tool("evaluate", labels, "--threads", "2")
    assert run.status != 0 and "No_such_clip_A" in run.err and "No_such_clip_B" not in run.err, run.describe()
