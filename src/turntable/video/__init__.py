"""From a video of a ball on a turntable to its film, and SYNTHETIC videos to test it.

`track.track_video` reads a video (`decode`, PyAV), finds the platter's rim, the ball and a
mark on the platter (`detect`, OpenCV), fits the camera and the platter's rate to the rim
and the mark (`calibrate`, on the pinhole model of `camera`) and finds the ball's centre,
R above the platter, from its image.  `render.render_video` renders SYNTHETIC
videos from the exact solutions.  `cli` is the command ``turntable track``; `plot` draws a
tracked video.  PyAV and OpenCV come with the extra ``turntable[video]``; without them the
modules import, and reading a video says what to install.
"""
