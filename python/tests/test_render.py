"""tumble.render_frame equals `tumble render`'s PNG of the same frame, pixel for pixel."""
import numpy as np
import pytest
from PIL import Image

import tumble
from conftest import SCENES


@pytest.mark.parametrize("scene,frame,aa", [("dzhanibekov.toml", 12, None), ("wing_nut.toml", 30, "msaa4")])
def test_render_frame_equals_cli_png(tmp_path, cli, scene, frame, aa):
    args = ["--aa", aa[:4], "--msaa", aa[4:]] if aa else []
    cli("render", SCENES / scene, "--frames", f"{frame}:{frame}", "--width", 192, "--height", 108,
        "--video", "none", "--out", tmp_path, *args)
    png = np.asarray(Image.open(tmp_path / f"frame_{frame:06d}.png").convert("RGB"))
    s = tumble.Scene.load(SCENES / scene)
    img = tumble.render_frame(s, frame=frame, width=192, height=108, aa=aa)
    assert img.shape == (108, 192, 3) and img.dtype == np.uint8
    assert png.shape == img.shape
    assert np.array_equal(img, png), f"{np.count_nonzero((img != png).any(axis=2))} pixels differ"
    # t = k/fps is the same frame.
    np.testing.assert_array_equal(tumble.render_frame(s, t=frame / s.output.fps, width=192, height=108, aa=aa), img)


def test_render_frame_between_frames_is_the_nearest_frame():
    s = tumble.Scene.load(SCENES / "dzhanibekov.toml")  # 30 fps
    np.testing.assert_array_equal(tumble.render_frame(s, t=0.01234, width=64, height=64),
                                  tumble.render_frame(s, frame=0, width=64, height=64))


def test_render_writes_what_the_cli_writes(tmp_path, cli):
    cli("render", SCENES / "thrown_box.toml", "--frames", "1:2", "--width", 64, "--height", 48, "--video", "none",
        "--out", tmp_path / "cli")
    summary = tumble.render(tumble.Scene.load(SCENES / "thrown_box.toml"), tmp_path / "py", frames="1:2", width=64,
                            height=48, video="none")
    assert "frames 1..2" in summary
    for k in (1, 2):
        name = f"frame_{k:06d}.png"
        assert (tmp_path / "py" / name).read_bytes() == (tmp_path / "cli" / name).read_bytes()
