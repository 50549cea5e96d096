/* orbit_camera.h — a camera circling a target point (z up), and the column-major 4x4 matrices
 * it needs, for the examples' GLFW programs. */
#ifndef HALFWING_EXAMPLES_ORBIT_CAMERA_H
#define HALFWING_EXAMPLES_ORBIT_CAMERA_H

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    float yaw, pitch;  /* radians; pitch stays short of the poles, where "up" degenerates */
    float distance;    /* from the target, world units */
    float target[3];
    float radius;      /* of the framed object, to scale zoom limits and clip planes */
} orbit_camera;

/* Looks at the box [lo, hi] from a three-quarter view, far enough to see all of it. */
void orbit_camera_frame(orbit_camera *camera, const float lo[3], const float hi[3]);

/* Turns by a mouse drag of (dx, dy) pixels. */
void orbit_camera_drag(orbit_camera *camera, double dx, double dy);

/* Zooms in (steps > 0) or out by scroll-wheel steps. */
void orbit_camera_zoom(orbit_camera *camera, double steps);

/* The eye position and the model-view-projection matrix for a viewport of this aspect ratio. */
void orbit_camera_mvp(const orbit_camera *camera, float aspect, float out_mvp[16], float out_eye[3]);

#ifdef __cplusplus
}
#endif

#endif
