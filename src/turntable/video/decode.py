"""Stage 1, decoding: a video's frames as ``Picture`` (luma and chroma planes, no copy), with
the times of the container (PyAV); ``lab`` turns a window of a picture into CIELAB."""

from __future__ import annotations

import os
import queue
import threading
from collections.abc import Iterable, Iterator
from fractions import Fraction
from pathlib import Path
from typing import Any, NamedTuple

import numpy as np
from numpy.typing import NDArray

from turntable._atomic import replacing

#: Word of a video's metadata (or file name) that marks it as rendered, not filmed.
SYNTHETIC = "SYNTHETIC"
#: Frames decoded ahead of the one the caller holds (a 720p frame is 1.4 MB).
AHEAD = 8


class VideoError(ValueError):
    """A video that cannot be tracked; the message says what is wrong, in one line.

    ``found``, when set, is what was found before the error (for ``--plot``).
    """

    def __init__(self, message: str, found: Any = None) -> None:
        super().__init__(message)
        self.found = found


class Picture(NamedTuple):
    """One frame as 4:2:0 Y'CbCr planes (uint8): luma (h, w), chroma (h/2, w/2) each, and
    whether the levels are full-range (0-255) rather than video-range (16-235)."""

    y: NDArray[np.uint8]
    cb: NDArray[np.uint8]
    cr: NDArray[np.uint8]
    full_range: bool

    @property
    def shape(self) -> tuple[int, int]:
        return self.y.shape  # type: ignore[return-value]

    def copy(self) -> Picture:
        return Picture(self.y.copy(), self.cb.copy(), self.cr.copy(), self.full_range)


class VideoInfo(NamedTuple):
    """What the container says of a video."""

    path: str
    width: int
    height: int
    frames: int
    codec: str
    rate: float
    metadata: dict[str, str]

    @property
    def synthetic(self) -> bool:
        """Whether the file name or the metadata say SYNTHETIC."""
        return SYNTHETIC in Path(self.path).name or any(
            SYNTHETIC in str(v) for v in self.metadata.values()
        )


def _import_av() -> Any:
    try:
        import av
    except ImportError:
        raise VideoError(
            "reading a video needs PyAV and OpenCV: pip install 'turntable[video]'"
        ) from None
    return av


class Video:
    """An open video: `info`, and `frames` yielding (index, time in s, grey image)."""

    def __init__(self, path: str | os.PathLike[str]) -> None:
        av = _import_av()
        name = os.fspath(path)
        if not Path(name).is_file():
            raise VideoError(f"{name}: no such file")
        try:
            self._container = av.open(name)
        except (av.error.FFmpegError, OSError, UnicodeDecodeError) as exc:
            raise VideoError(f"{name}: not a video that can be read ({exc})") from None
        if not self._container.streams.video:
            self._container.close()
            raise VideoError(f"{name}: the file holds no video stream")
        stream = self._container.streams.video[0]
        stream.thread_type = "AUTO"
        self._stream = stream
        self._ahead: _Ahead | None = None
        rate = float(stream.average_rate or stream.guessed_rate or 0.0)
        self.info = VideoInfo(
            name,
            stream.codec_context.width,
            stream.codec_context.height,
            int(stream.frames or 0),
            stream.codec_context.name,
            rate,
            {str(k): str(v) for k, v in self._container.metadata.items()},
        )

    def frames(self) -> Iterator[tuple[int, float, Picture]]:
        """Yield (index, time in s from the container's timestamps, picture).

        The frames are decoded in a thread of their own, up to `AHEAD` ahead of the caller
        (PyAV lets other threads run while FFmpeg decodes): what the caller does with a frame
        and the decoding of the next ones take their turns on different cores."""
        av = _import_av()
        name = self.info.path
        self._ahead = _Ahead(
            ((frame.time, _picture(frame)) for frame in self._container.decode(self._stream)),
            AHEAD,
        )
        index = -1
        try:
            for frame_time, picture in self._ahead:
                index += 1
                if frame_time is not None:
                    time = float(frame_time)
                elif self.info.rate > 0:
                    time = index / self.info.rate
                else:
                    raise VideoError(f"{name}: frame {index} has no timestamp and no frame rate")
                yield index, time, picture
        except av.error.FFmpegError as exc:
            raise VideoError(f"{name}: cannot decode frame {index + 1} ({exc})") from None
        finally:
            self._ahead.stop()

    def close(self) -> None:
        if self._ahead is not None:
            self._ahead.stop()  # before the container it decodes is closed
        self._container.close()

    def __enter__(self) -> Video:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()


class _Ahead:
    """The items of `items`, taken in a thread of its own up to `size` ahead of the caller; an
    exception raised there is raised again where the caller iterates."""

    def __init__(self, items: Iterable[Any], size: int) -> None:
        self._queue: queue.Queue[tuple[bool, Any]] = queue.Queue(size)
        self._stopped = threading.Event()
        self._thread = threading.Thread(target=self._take, args=(items,), daemon=True)
        self._thread.start()

    def _take(self, items: Iterable[Any]) -> None:
        try:
            for item in items:
                if not self._put((True, item)):
                    return
        except BaseException as exc:  # raised again in the caller's thread
            self._put((False, exc))
        else:
            self._put((False, None))

    def _put(self, entry: tuple[bool, Any]) -> bool:
        while not self._stopped.is_set():
            try:
                self._queue.put(entry, timeout=0.05)
                return True
            except queue.Full:
                pass
        return False

    def __iter__(self) -> Iterator[Any]:
        while True:
            taken, item = self._queue.get()
            if taken:
                yield item
            elif item is None:
                return
            else:
                raise item

    def stop(self) -> None:
        """Stop taking items (the thread ends within 0.05 s of its current item)."""
        self._stopped.set()
        self._thread.join()


def _picture(frame: Any) -> Picture:
    """The planes of a 4:2:0 frame as they are (no copy); other formats converted to it."""
    name = frame.format.name
    if name not in ("yuv420p", "yuvj420p"):
        frame = frame.reformat(format="yuv420p")
        name = "yuv420p"
    planes = []
    for k, plane in enumerate(frame.planes):
        h = frame.height if k == 0 else (frame.height + 1) // 2
        w = frame.width if k == 0 else (frame.width + 1) // 2
        planes.append(np.frombuffer(plane, np.uint8).reshape(h, plane.line_size)[:, :w])
    full = name == "yuvj420p" or int(getattr(frame, "color_range", 0) or 0) == 2
    return Picture(planes[0], planes[1], planes[2], full)


def window(centre: tuple[float, float], half: float, shape: tuple[int, int]) -> tuple[slice, slice]:
    """The window of half-width ``half`` px about ``centre`` (u, v), cut to the image."""
    u, v = centre
    return (
        slice(max(int(v - half), 0), min(int(v + half) + 2, shape[0])),
        slice(max(int(u - half), 0), min(int(u + half) + 2, shape[1])),
    )


def lab(picture: Picture, box: tuple[slice, slice] | None = None) -> NDArray[np.float32]:
    """CIELAB (L 0-100, a and b about -100-100; D65, sRGB primaries taken for BT.601's) of the
    window ``box`` of a picture (rows, columns; all of it by default), shape (h, w, 3)."""
    import cv2

    return cv2.cvtColor(_rgb(picture, box), cv2.COLOR_RGB2Lab)


def rgb(picture: Picture) -> NDArray[np.uint8]:
    """The whole picture as RGB, uint8 (for drawing)."""
    return (_rgb(picture, None) * 255.0 + 0.5).astype(np.uint8)


def _rgb(picture: Picture, box: tuple[slice, slice] | None) -> NDArray[np.float32]:
    """RGB in [0, 1] of a window, the chroma interpolated to the luma's pixels with H.264's
    default siting (a chroma sample beside luma column 2i, between rows 2j and 2j + 1)."""
    import cv2

    rows, cols = box or (slice(0, picture.y.shape[0]), slice(0, picture.y.shape[1]))
    y = picture.y[rows, cols]
    h, w = y.shape
    # dst (x, y) of the window -> chroma (x / 2, (y - 0.5) / 2), both offset by the window
    m = np.array([[0.5, 0.0, cols.start / 2.0], [0.0, 0.5, (rows.start - 0.5) / 2.0]], np.float32)
    flags = cv2.INTER_LINEAR | cv2.WARP_INVERSE_MAP
    cb, cr = (
        cv2.warpAffine(c, m, (w, h), flags=flags, borderMode=cv2.BORDER_REPLICATE)
        for c in (picture.cb, picture.cr)
    )
    ycbcr = cv2.merge([np.ascontiguousarray(y), cb, cr]).astype(np.float32)
    rgb = cv2.transform(ycbcr, _YCBCR_TO_RGB[picture.full_range])
    return np.clip(rgb, 0.0, 1.0, out=rgb)


def _ycbcr_to_rgb(full_range: bool) -> NDArray[np.float64]:
    """(R, G, B) = M (Y, Cb, Cr, 1), BT.601, in [0, 1]: Y of 16-235 and Cb, Cr of 16-240 about
    128 (or 0-255 where ``full_range``)."""
    ay, by = (1 / 255, 0.0) if full_range else (1 / 219, -16 / 219)
    ac = 1 / 255 if full_range else 1 / 224
    cb, cr = np.array([[0.0, 1.402], [-0.344136, -0.714136], [1.772, 0.0]]).T * ac
    return np.column_stack([np.full(3, ay), cb, cr, by - 128 * (cb + cr)])


_YCBCR_TO_RGB = {full: _ycbcr_to_rgb(full) for full in (False, True)}


def yuv420(rgb_img: NDArray[np.uint8]) -> NDArray[np.uint8]:
    """An RGB image (h, w, 3 or 4; h and w even) as one 4:2:0 video-range BT.601 frame, shape
    (3 h / 2, w), for ``av.VideoFrame.from_ndarray(..., format="yuv420p")``: the inverse of
    ``lab``'s reading, with the same (H.264's) chroma siting."""
    x = rgb_img[..., :3].astype(np.float32) / 255.0
    h, w = x.shape[:2]
    y = 16.0 + 219.0 * (x @ np.array([0.299, 0.587, 0.114], np.float32))
    cb = 128.0 + 224.0 * (x @ np.array([-0.168736, -0.331264, 0.5], np.float32))
    cr = 128.0 + 224.0 * (x @ np.array([0.5, -0.418688, -0.081312], np.float32))
    planes = [y]
    for c in (cb, cr):
        rows = (c[0::2] + c[1::2]) / 2  # between rows 2j and 2j + 1
        left = np.concatenate([rows[:, :1], rows[:, 1:-1:2]], axis=1)  # column 2i - 1
        planes.append(0.25 * left + 0.5 * rows[:, 0::2] + 0.25 * rows[:, 1::2])
    out = np.concatenate([planes[0].ravel(), planes[1].ravel(), planes[2].ravel()])
    return np.clip(out + 0.5, 0, 255).astype(np.uint8).reshape(3 * h // 2, w)


def write_video(
    path: Path,
    frames: Iterator[tuple[float, NDArray[np.uint8]]],
    fps: float,
    size: tuple[int, int],
    crf: int,
    comment: str,
) -> None:
    """Write (time in s, RGB image) frames as H.264 (libx264, `yuv420`, times to 1/90000 s)
    with the metadata of a SYNTHETIC video: under a temporary name, renamed when complete."""
    import av

    time_base = Fraction(1, 90000)
    with replacing(path) as tmp, av.open(str(tmp), "w") as out:
        out.metadata["title"] = f"{SYNTHETIC} turntable video"
        out.metadata["comment"] = f"{SYNTHETIC}: {comment}, not filmed"
        stream = out.add_stream("libx264", rate=Fraction(fps).limit_denominator(10000))
        stream.width, stream.height = size
        stream.pix_fmt = "yuv420p"
        stream.time_base = time_base
        stream.codec_context.time_base = time_base
        stream.options = {"crf": str(crf), "preset": "ultrafast"}
        for t, img in frames:
            frame = av.VideoFrame.from_ndarray(yuv420(img), format="yuv420p")
            frame.pts = round(t / time_base)
            frame.time_base = time_base
            out.mux(stream.encode(frame))
        out.mux(stream.encode(None))
