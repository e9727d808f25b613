"""Notebook display: `tumble.show(scene)` is the scene as an inline video, `tumble.show(scene, t=1.0)` one frame.

Both are IPython display objects (IPython.display.Video, IPython.display.Image): the last line of a notebook
cell shows them, `IPython.display.display(...)` shows them anywhere. The pixels are `tumble render`'s."""
import pathlib
import tempfile

from . import _tumble


def show(scene, t=None, *, frame=None, width=960, height=None, aa=None, gl=""):
    """The scene as an inline video (H.264 MP4, embedded), or with `t` (s) or `frame` one rendered frame (PNG).

    width defaults to 960 px, a size at which the overlay's text reads; height follows the scene's aspect.
    A frame at `t` is the frame nearest to t (see render_frame). The video renders every frame of the scene as
    `tumble render` does (frames, then ffmpeg), in a temporary folder that is removed."""
    from IPython.display import Image, Video  # IPython comes with Jupyter (python3-ipykernel)

    out = scene.output
    if height is None:
        height = max(16, round(width * out.height / out.width / 2) * 2)  # even: H.264 needs it
    if t is not None or frame is not None:
        import io
        from PIL import Image as PILImage  # matplotlib's PNG writer (python3-pil)
        pixels = _tumble.render_frame(scene, t, frame=frame, width=width, height=height, aa=aa, gl=gl)
        buf = io.BytesIO()
        PILImage.fromarray(pixels).save(buf, format="PNG")
        return Image(data=buf.getvalue(), format="png", width=width)
    with tempfile.TemporaryDirectory(prefix="tumble-show-") as folder:
        _tumble.render(scene, folder, width=width, height=height, aa=aa, video="mp4", gl=gl)
        video = next(pathlib.Path(folder).glob("*.mp4"))
        return Video(data=video.read_bytes(), embed=True, mimetype="video/mp4", width=width,
                     html_attributes="controls loop")
