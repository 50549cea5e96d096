#include "orbit_camera.h"

#include <math.h>
#include <string.h>

#define PITCH_LIMIT 1.55f

static void mat_mul(float out[16], const float a[16], const float b[16]) {
    float r[16];
    for (int c = 0; c < 4; ++c)
        for (int row = 0; row < 4; ++row) {
            float s = 0.0f;
            for (int k = 0; k < 4; ++k) s += a[k * 4 + row] * b[c * 4 + k];
            r[c * 4 + row] = s;
        }
    memcpy(out, r, sizeof r);
}

static void perspective(float out[16], float fovy, float aspect, float znear, float zfar) {
    float f = 1.0f / tanf(fovy / 2.0f);
    memset(out, 0, 16 * sizeof(float));
    out[0] = f / aspect;
    out[5] = f;
    out[10] = (zfar + znear) / (znear - zfar);
    out[11] = -1.0f;
    out[14] = 2.0f * zfar * znear / (znear - zfar);
}

static void normalize3(float v[3]) {
    float len = sqrtf(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (len > 0.0f) v[0] /= len, v[1] /= len, v[2] /= len;
}

static void cross3(float out[3], const float a[3], const float b[3]) {
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

static void look_at(float out[16], const float eye[3], const float target[3]) {
    const float up[3] = {0, 0, 1};
    float f[3] = {target[0] - eye[0], target[1] - eye[1], target[2] - eye[2]}, s[3], u[3];
    normalize3(f);
    cross3(s, f, up);
    normalize3(s);
    cross3(u, s, f);
    float m[16] = {s[0], u[0], -f[0], 0, s[1], u[1], -f[1], 0, s[2], u[2], -f[2], 0,
                   -(s[0] * eye[0] + s[1] * eye[1] + s[2] * eye[2]),
                   -(u[0] * eye[0] + u[1] * eye[1] + u[2] * eye[2]),
                   f[0] * eye[0] + f[1] * eye[1] + f[2] * eye[2], 1};
    memcpy(out, m, sizeof m);
}

void orbit_camera_frame(orbit_camera *camera, const float lo[3], const float hi[3]) {
    float radius = 0.0f;
    for (int axis = 0; axis < 3; ++axis) {
        int empty = !(lo[axis] <= hi[axis]);
        camera->target[axis] = empty ? 0.0f : 0.5f * (lo[axis] + hi[axis]);
        radius += empty ? 0.0f : 0.25f * (hi[axis] - lo[axis]) * (hi[axis] - lo[axis]);
    }
    camera->radius = radius > 0.0f ? sqrtf(radius) : 1.0f;
    /* A three-quarter view from slightly below: models sit on z = 0 with their openings more
     * often at the bottom than at the top (the bundled capsule has one there). */
    camera->yaw = -1.1f;
    camera->pitch = -0.35f;
    /* A 45 degree field of view sees a sphere of this radius from 2.6 radii away; the radius is
     * half the box diagonal, an overestimate, so a little less still frames it. */
    camera->distance = 2.4f * camera->radius;
}

void orbit_camera_drag(orbit_camera *camera, double dx, double dy) {
    camera->yaw -= (float)dx * 0.01f;
    camera->pitch += (float)dy * 0.01f;
    if (camera->pitch > PITCH_LIMIT) camera->pitch = PITCH_LIMIT;
    if (camera->pitch < -PITCH_LIMIT) camera->pitch = -PITCH_LIMIT;
}

void orbit_camera_zoom(orbit_camera *camera, double steps) {
    camera->distance *= powf(0.9f, (float)steps);
    if (camera->distance < 0.05f * camera->radius) camera->distance = 0.05f * camera->radius;
    if (camera->distance > 50.0f * camera->radius) camera->distance = 50.0f * camera->radius;
}

void orbit_camera_mvp(const orbit_camera *camera, float aspect, float out_mvp[16], float out_eye[3]) {
    float view[16], projection[16];
    out_eye[0] = camera->target[0] + camera->distance * cosf(camera->pitch) * cosf(camera->yaw);
    out_eye[1] = camera->target[1] + camera->distance * cosf(camera->pitch) * sinf(camera->yaw);
    out_eye[2] = camera->target[2] + camera->distance * sinf(camera->pitch);
    look_at(view, out_eye, camera->target);
    /* Clip planes that follow the distance keep depth precision whatever the model's scale. */
    float znear = fmaxf(camera->distance - 2.0f * camera->radius, 0.01f * camera->radius);
    perspective(projection, 45.0f * 3.14159265f / 180.0f, aspect > 0.0f ? aspect : 1.0f, znear,
                camera->distance + 2.0f * camera->radius);
    mat_mul(out_mvp, projection, view);
}
