"""Pixel projection of MuJoCo's free camera, for the picture tests
(check_render.py, check_view.py): the camera looks at `look` from `dist` m
away, azimuth and elevation in degrees (MuJoCo's mjvCamera), vertical field
of view fovy in degrees, into a w x h picture (x right, y down from the top
left). A pinhole camera: pixel = centre + f (d . right, -d . up) / (d . fwd)
with f = (h / 2) / tan(fovy / 2)."""

import math


def projector(look, dist, az, el, fovy, w, h):
    """(project, horizon): project(q) gives the pixel of world point q;
    horizon is the picture row of rays at elevation 0 (negative: above it)"""
    a, e = math.radians(az), math.radians(el)
    fwd = [math.cos(e) * math.cos(a), math.cos(e) * math.sin(a), math.sin(e)]
    up = [-math.sin(e) * math.cos(a), -math.sin(e) * math.sin(a), math.cos(e)]
    right = [fwd[1] * up[2] - fwd[2] * up[1], fwd[2] * up[0] - fwd[0] * up[2],
             fwd[0] * up[1] - fwd[1] * up[0]]
    eye = [look[i] - dist * fwd[i] for i in range(3)]
    f = (h / 2) / math.tan(math.radians(fovy) / 2)

    def project(q):
        d = [q[i] - eye[i] for i in range(3)]
        z = sum(d[i] * fwd[i] for i in range(3))
        return (w / 2 + f * sum(d[i] * right[i] for i in range(3)) / z,
                h / 2 - f * sum(d[i] * up[i] for i in range(3)) / z)
    return project, h / 2 - f * math.tan(-e)
