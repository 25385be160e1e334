/* distort_project CAMERA: the camera model of glsplay (runtime/camera/distort.h)
 * as a filter, for tests/py/check_distortion.py, which compares it with
 * cv2.projectPoints and cv2.fisheye.projectPoints.  Each input line is
 *   w X Y Z   a world point: prints "u v" (through the lens model)
 *   p U V     a pixel: prints "x y iterations" (its undistorted ray
 *             (x, y, 1) by the inverse model; iterations -1: none)
 * numbers printed with 17 significant digits.  Exit 1 if the camera file
 * is refused (its message on stderr), 2 on usage. */
#include <stdio.h>
#include <string.h>
#include "camera.h"
#include "distort.h"

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: distort_project CAMERA < points\n");
        return 2;
    }
    gls_camera c;
    char err[2048], line[512];
    if (gls_camera_load(argv[1], GLS_POSE_UNDECLARED, stderr, &c, err, sizeof err)) {
        fprintf(stderr, "%s\n", err);
        return 1;
    }
    while (fgets(line, sizeof line, stdin)) {
        double a, b, z;
        if (sscanf(line, "w %lf %lf %lf", &a, &b, &z) == 3) {
            double P[3] = {a, b, z}, Pc[3], u, v;
            gls_camera_to_cam(&c, P, Pc);
            gls_distort_project(&c, Pc, &u, &v);
            printf("%.17g %.17g\n", u, v);
        } else if (sscanf(line, "p %lf %lf", &a, &b) == 2) {
            double x, y;
            int it = gls_distort_pixel_ray(&c, a, b, &x, &y);
            printf("%.17g %.17g %d\n", x, y, it);
        } else {
            fprintf(stderr, "distort_project: error: cannot read: %s", line);
            return 1;
        }
    }
    return 0;
}
