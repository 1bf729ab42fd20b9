"""The real animations of the shared data (horse gallop, samba, cat poses), unpacked into the
scratch folder."""

import pytest

from conftest import matches_all, succeeds

UNPACKED = {"data": ("horse-gallop", 48), "samba": ("samba", 175), "cat": ("cat-poses", 10)}


@pytest.mark.parametrize("archive", list(UNPACKED))
def test_unpack(real_data, archive):
    folder, frames = UNPACKED[archive]
    assert len(list((real_data / folder).glob("*.obj"))) == frames


# The cat folder's rest pose sorts into the frames, as frame 9: --files shows it, and the rest
# pose kept apart with --reference-mesh measures the nine poses against it.
def test_info_files_cat(tool, real_data):
    matches_all(succeeds(tool("info", real_data / "cat-poses", "--files")).output,
                r" +0: [^\n]*cat-01.obj\n", r" +9: [^\n]*cat-reference.obj\n")


def test_strain_cat_reference_mesh(tool, real_data):
    cats = real_data / "cat-poses"
    strain = tool("strain", f"{cats}/cat-0*.obj", "--reference-mesh", cats / "cat-reference.obj", "--json", "-").json()
    assert strain["frames"] == 9 and strain["reference_mesh"].endswith("cat-reference.obj")


def test_info_horse_gallop(tool, real_data):
    matches_all(succeeds(tool("info", real_data / "horse-gallop")).output,
                r"frames +48\n", r"vertices +8431\n", r"triangles +16843\n", r"format +obj\n")


def test_info_samba(tool, real_data):
    info = tool("info", real_data / "samba", "--json", "-").json()
    assert (info["frames"], info["vertices"], info["triangles"]) == (175, 9971, 19938)


def test_strain_horse_gallop(tool, real_data):
    strain = tool("strain", real_data / "horse-gallop", "--json", "-").json()
    assert (strain["frames"], strain["triangles"], strain["degenerate_count"]) == (48, 16843, 0)


def test_temporal_horse_gallop(tool, real_data):
    result = tool("temporal", real_data / "horse-gallop", "--json", "-").json()
    assert result["frames"] == 48 and result["segments"][-1]["last"] == 47


def test_info_glob(tool, real_data):
    assert tool("info", f"{real_data}/horse-gallop/000*.obj", "--json", "-").json()["frames"] == 9
