/* ffl-test: osmesa-diff */
/*
 * OSMesa vs the spec: glInterleavedArrays and the GL 1.4 arrays.
 *
 * GL 1.5 §2.8 defines glInterleavedArrays by a command sequence that starts
 * with DisableClientState(EDGE_FLAG_ARRAY), (INDEX_ARRAY),
 * (SECONDARY_COLOR_ARRAY) and (FOG_COORD_ARRAY). OSMesa disables the edge
 * flag and index arrays but leaves the secondary color and fog coordinate
 * arrays enabled.
 */
#include "ffl_test.h"

int main(void)
{
    static const GLfloat data[3 * 3] = { 0, 0, 0, 1, 0, 0, 0, 1, 0 };

    ffl_test_init();
    glSecondaryColorPointer(3, GL_FLOAT, 0, data);
    glFogCoordPointer(GL_FLOAT, 0, data);
    glEnableClientState(GL_SECONDARY_COLOR_ARRAY);
    glEnableClientState(GL_FOG_COORD_ARRAY);
    glEnableClientState(GL_EDGE_FLAG_ARRAY);
    glInterleavedArrays(GL_V3F, 0, data);
    printf("secondary_color_array enabled %d ref enabled 0\n",
           (int)glIsEnabled(GL_SECONDARY_COLOR_ARRAY));
    printf("fog_coord_array enabled %d ref enabled 0\n", (int)glIsEnabled(GL_FOG_COORD_ARRAY));
    printf("edge_flag_array enabled %d ref enabled 0\n", (int)glIsEnabled(GL_EDGE_FLAG_ARRAY));
    return 0;
}
