"""The docs' pictures read at the course site's width: the home page's office (docs/office.png) and viewer
(docs/viewer.png), and docs/viewer.md's JupyterLab screenshot (docs/jupyterlab.png). Each is the size its tool makes
(tools/viewer_picture.py, tools/lab_browser.py), which the site's column shrinks little. Readers of the site found the
earlier 1400 and 1280 px pictures, shown at half size, unreadable (text 6-8 px)."""

from pathlib import Path

from PIL import Image

from tools import lab_browser, viewer_picture

ROOT = Path(__file__).resolve().parents[1]
DOCS = ROOT / "docs"
COLUMN = 688  # px: the width at which the site shows a wide picture in a 1280 px window (mkdocs-material's column)
SHRINK = 0.8  # the least share of its size a picture keeps there: 13 px text stays above 10 px (8 pt)


def size(png: str) -> tuple[int, int]:
    with Image.open(DOCS / png) as image:
        return image.size


def test_the_jupyterlab_picture_is_one_cell_of_a_narrow_window_at_twice_the_pixels():
    """Since review r25b, the cell from its 3D view down: its code filled a third of the picture, and the still
    above the view repeated it small."""
    width, height = size("jupyterlab.png")
    window, scale = lab_browser.SHOT_WINDOW, lab_browser.SHOT_SCALE
    again = "again: TOOLKIT_QUICK=1 python -m tools.lab_browser notebooks/05_3d_scenes.ipynb --view-only --screenshot"
    assert window[0] < width <= window[0] * scale, again  # twice the pixels of a window no wider than SHOT_WINDOW
    assert (width, height) != lab_browser.WINDOW, again  # one cell, not the page
    assert height <= lab_browser.SHOT_HEIGHT * scale, again  # the cell whole (reader r23b: a tall one was cut off)
    assert COLUMN / (width / scale) >= SHRINK


def test_the_viewer_picture_is_the_narrow_window_its_tool_photographs_at_twice_the_pixels():
    """Reader r18c: at 800 px, shown at 688, the panel's slider labels could not be read. A window narrower than the
    column is shown larger than its own size, its text too (the picture has the pixels for it)."""
    window, scale = viewer_picture.WINDOW, viewer_picture.SCALE
    shot = (round(window[0] * scale), round(window[1] * scale))
    assert size("viewer.png") == shot, "make it again: python -m tools.viewer_picture docs/viewer.png"
    assert COLUMN / window[0] > 1 and scale >= 2


def test_the_viewer_picture_leaves_most_of_the_scene_clear_of_its_panel():
    """Reader r25b: the panel, 340 px of a 680 px window and cut off at "Layers", hid the blocks behind it. Narrowed,
    with two folders folded, it ends above the window's foot and covers under a third of the picture."""
    from toolkit.viewer import browser

    assert viewer_picture.PANEL_WIDTH / viewer_picture.WINDOW[0] < 0.4 < browser.PANEL_PX / viewer_picture.WINDOW[0]
    assert set(viewer_picture.FOLD) == {"Workspace", "Samples"}


def test_the_home_pages_viewer_caption_says_what_to_look_at():
    """Reader r28e: the caption called four folders folded where chapter 05 says two. Reader r41e, home lift 4: it
    then read as notes on how the picture was made; it now says what the marks, the robot's colour and the sliders
    are, and no folder at all (the picture folds some, :data:`FOLD`, so a count of folders would be the picture's)."""
    readme = " ".join((ROOT / "README.md").read_text().split())
    caption = readme.partition("*The viewer on the 3D office")[2].partition("*")[0]
    assert caption.startswith(f", with {viewer_picture.SAMPLES} uniform samples: blue circles are valid, vermillion")
    assert 'the panel\'s line "exact: valid"' in caption and "sliders" in caption
    assert "fold" not in caption and "yellow" not in caption


def test_the_viewer_picture_outlines_the_office_on_its_floor_alone():
    """Reader r23b: a stray stroke poked out above the panel, an upright edge of the office's outline (6 units tall)
    whose foot the panel hides. The picture keeps the outline's four floor edges."""
    import numpy as np

    from toolkit import scenarios
    from toolkit.viewer import drawing

    workspace = scenarios.get(viewer_picture.SCENARIO).make_workspace(np.random.default_rng(viewer_picture.SEED))
    edges = drawing.region_edges(workspace)  # (12, 2, 3)
    floor = viewer_picture.floor_outline(edges)
    assert floor.shape == (4, 2, 3) and np.all(floor[..., 2] == workspace.lower[2])
    assert np.ptp(edges[..., 2]) > 0  # the whole outline has height: the upright edges are what the picture leaves out


def test_the_home_pages_office_link_is_chapter_05s_still():
    """Reader r27e: the home page's first picture, a JupyterLab screenshot close to the robot, showed a dozen marks
    and no outline. docs/office.png is chapter 05's section 2 still, its overview alone, from the chapter's samples;
    "most of them the platform at its edge" (the still's diamonds outside the office) is checked too. Reader r32e
    found the still answered no question of the home page: chapter 05's row links it, and the page no longer shows
    it or its caption."""
    import numpy as np

    from toolkit import scenarios
    from toolkit.geometry.collision import exact_checker
    from toolkit.geometry.workspace import Workspace
    from toolkit.plots.still_panels import overview_step

    width, height = size("office.png")
    assert COLUMN / width >= 0.7 and width > COLUMN and height < width, "python -m tools.viewer_picture --office"
    office = scenarios.get(viewer_picture.SCENARIO)
    workspace = office.make_workspace(np.random.default_rng(viewer_picture.SEED))
    Q = viewer_picture.office_samples()  # chapter 05's: its N_SAMPLES at full size, from its SEED
    assert overview_step(len(Q)) == 10  # "one in ten drawn"
    chapter = (ROOT / "notebooks" / "05_3d_scenes.ipynb").read_text()
    assert f"N_SAMPLES = sized(full={len(Q)}," in chapter and f"SEED = {viewer_picture.SEED} " in chapter
    colliding = ~exact_checker(workspace, office.robot).are_valid(Q)
    empty = Workspace(workspace.lower, workspace.upper, np.zeros((0, 2, 3)), family=workspace.family)
    outside = colliding & ~exact_checker(empty, office.robot).are_valid(Q)
    platform = office.robot.link_aabbs(Q)[:, 0]  # (N, 2, 3): the platform's box, the first link
    off = np.any((platform[:, 0, :2] < workspace.lower[:2]) | (platform[:, 1, :2] > workspace.upper[:2]), axis=1)
    assert 2 * (outside & off).sum() > outside.sum()  # "most of them the platform at its edge"
    assert (~colliding).sum() and (colliding & ~outside).sum() and outside.sum()  # both kinds of diamond are drawn
    readme = " ".join((ROOT / "README.md").read_text().split())
    # reader r32e, lift 2: the still answered no question of the home page; chapter 05's row links it instead
    assert "[a still of its office](docs/office.png)" in readme and "[![Chapter 05's office" not in readme
    assert "docs/jupyterlab.png" not in readme
