"""Reading a video: its frames as grey images, with the times of the container (PyAV)."""

from __future__ import annotations

import os
from collections.abc import Iterator
from pathlib import Path
from typing import Any, NamedTuple

import numpy as np
from numpy.typing import NDArray

#: Word of a video's metadata (or file name) that marks it as rendered, not filmed.
SYNTHETIC = "SYNTHETIC"


class VideoError(ValueError):
    """A video that cannot be tracked; the message says what is wrong, in one line."""


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

    def frames(self) -> Iterator[tuple[int, float, NDArray[np.uint8]]]:
        """Yield (index, time in s from the container's timestamps, grey image)."""
        av = _import_av()
        name = self.info.path
        index = -1
        try:
            for frame in self._container.decode(self._stream):
                index += 1
                if frame.time is not None:
                    time = float(frame.time)
                elif self.info.rate > 0:
                    time = index / self.info.rate
                else:
                    raise VideoError(f"{name}: frame {index} has no timestamp and no frame rate")
                yield index, time, _grey(frame)
        except av.error.FFmpegError as exc:
            raise VideoError(f"{name}: cannot decode frame {index + 1} ({exc})") from None

    def close(self) -> None:
        self._container.close()

    def __enter__(self) -> Video:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()


def _grey(frame: Any) -> NDArray[np.uint8]:
    """The luma plane of a YUV frame as it is (no copy), else a conversion to grey."""
    name = frame.format.name
    if name.startswith(("yuv", "yuvj", "nv12", "nv21", "gray")) and not name.startswith(
        ("gray16", "gray10", "gray12", "yuv420p10", "yuv422p10", "yuv444p10")
    ):
        plane = frame.planes[0]
        data = np.frombuffer(plane, np.uint8).reshape(frame.height, plane.line_size)
        return data[:, : frame.width]
    return frame.to_ndarray(format="gray")
