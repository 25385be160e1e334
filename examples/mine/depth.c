/* The README's C example: the depth at one pixel of the demo's left camera. */
#include <stdio.h>
#include <glscene.h>
int main(void)
{
    static float depth[480 * 640];
    glscene_error e;
    glscene_camera cam;
    glscene_buffers out = {.depth = depth}; /* also .rgb8, .instance, .normals */
    glscene_player *p = glscene_open("build/demo.glsb", NULL, &e);
    if (!p || glscene_camera_from_file("examples/demo/left.cam", &cam, &e) || glscene_render(p, &cam, &out, &e))
        return printf("%s\n", e.message), 1;
    printf("depth at (400, 460): %g m\n", depth[460 * cam.width + 400]);
    glscene_close(p);
    return 0;
}
