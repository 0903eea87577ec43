/* ffl-test: differential */
/*
 * Image commands in display lists (§5.4): glTexImage2D, glTexSubImage2D and
 * glPolygonStipple are compiled with their pixels unpacked under the pixel store modes in
 * force when the list is compiled (glPixelStore itself is not compiled, it runs at once);
 * executing the list later, under other modes, gives the images as they were given. Read
 * back with glGetTexImage and glGetPolygonStipple.
 */
#include "ffl_test.h"

int main(void)
{
    GLubyte pixels[4 * 4 * 4], back[2 * 2 * 4], stipple[4 * 32 + 8], stipple_back[128];
    GLuint list, texture;
    int k;

    ffl_test_init();
    for (k = 0; k < (int)sizeof pixels; k++)
        pixels[k] = (GLubyte)(k * 7 + 1);
    for (k = 0; k < (int)sizeof stipple; k++)
        stipple[k] = (GLubyte)(k * 13 + 5);
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);

    /* Rows of 4 pixels, the first row and pixel skipped; stipple rows of 4 bytes (row
     * length 4 bits, aligned to 4), the LSB first: the stipple then reads 133 bytes. */
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 4);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 1);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 1);
    glPixelStorei(GL_UNPACK_LSB_FIRST, GL_TRUE);
    list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 1, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixels + 32);
    glPolygonStipple(stipple);
    glEndList();
    ffl_print_error("compile");
    ffl_print_ints("unpack row length after compile", GL_UNPACK_ROW_LENGTH, 1);

    /* Nothing ran at compile time. */
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, (GLint *)back);
    printf("width before call %d\n", (int)*(GLint *)back);

    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
    glPixelStorei(GL_UNPACK_LSB_FIRST, GL_FALSE);
    glCallList(list);
    ffl_print_error("call");
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
    printf("texture");
    for (k = 0; k < (int)sizeof back; k++)
        printf(" %d", (int)back[k]);
    printf("\n");
    glGetPolygonStipple(stipple_back);
    printf("stipple");
    for (k = 0; k < 16; k++)
        printf(" %d", (int)stipple_back[k]);
    printf("\n");
    ffl_print_error("read back");
    glDeleteLists(list, 1);
    glDeleteTextures(1, &texture);
    return 0;
}
