"""From a video of a ball on a turntable to its film, and SYNTHETIC videos to test it.

`track.track_video` runs the stages in order, each taking and returning plain data:
`decode` (frames and their times, PyAV; colour as CIELAB), `platter` (the rim), `find` (the
ball and the mark, told apart by how they move; seeds), `follow` (both through the video;
`blobs`: blobs of a colour and the ball's outline), `calibrate` (the camera, the platter's
rate and a rolling shutter's readout, on the pinhole model of `camera`) and `check` (a track
that contradicts itself is refused).  `render.render_video` renders SYNTHETIC videos from the
exact solutions.  ``cli`` is the command ``turntable track``; ``plot`` draws a tracked video, or
what was found before an error.  PyAV and OpenCV come with the extra ``turntable[video]``;
without them the modules import, and reading a video says what to install.
"""
