/* Generates the benchmark scene for `make bench-compile`: a terrain of
 * triangle strips (a height field sampled on a grid, in millimetres with
 * three decimals, as a road generator or a CAD export writes them) plus
 * per-vertex colours on every fourth strip.  Deterministic.
 * usage: gen_scene ROWS COLS > Terrain.scene   (vertices = ROWS * 2 * COLS) */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

int main(int argc, char **argv)
{
    int rows = argc > 1 ? atoi(argv[1]) : 500, cols = argc > 2 ? atoi(argv[2]) : 1000;
    const double step = 250.0; /* 25 cm grid */
    printf("// benchmark terrain: %d strips of %d vertices\nconst ox = 1500000;\n", rows, 2 * cols);
    for (int r = 0; r < rows; r++) {
        int coloured = r % 4 == 0;
        printf("tstrip {\n");
        for (int c = 0; c < cols; c++) {
            for (int k = 0; k < 2; k++) {
                double x = c * step, z = (r + k) * step;
                double y = 800.0 * sin(x * 1e-4) * cos(z * 1.3e-4) + 37.0 * sin(x * 3e-3 + z * 2e-3);
                if (coloured)
                    printf("  col(%.3f, %.3f, 0.2);", 0.3 + 0.2 * sin(x * 1e-3), 0.6 + 0.1 * cos(z * 1e-3));
                printf("  vert(%.3f, %.3f, %.3f);\n", x, y, z);
            }
        }
        printf("}\n");
    }
    return 0;
}
