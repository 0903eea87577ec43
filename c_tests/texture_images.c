/* ffl-test: differential */
/*
 * Texture images (§3.8.1-3.8.3, §6.1.3-6.1.4): images uploaded in several internal formats,
 * formats and types under the unpack modes (alignment, row length, skips, swap bytes), read
 * back with glGetTexImage in several formats and types under the pack modes, the level
 * parameters, sub-images, proxies, GL_GENERATE_MIPMAP, and the errors. Internal formats
 * whose resolution an implementation chooses (RGB5, the 4- and 12-bit ones) are not read
 * back; neither are copies from the framebuffer (fflight's holds nothing drawn). Left out
 * (osmesa-differences.md 5 and 16): signed types (GL 1.5's (2c + 1) / (2^b - 1)), sizes
 * that are not 2^n plus the border, glCopyTexImage with internal format 1-4, an absent
 * image's internal format, pixel transfer results exactly halfway between two steps.
 */
#include "ffl_test.h"

static const GLenum level_pnames[11] = {
    GL_TEXTURE_WIDTH, GL_TEXTURE_HEIGHT, GL_TEXTURE_DEPTH, GL_TEXTURE_BORDER,
    GL_TEXTURE_INTERNAL_FORMAT, GL_TEXTURE_RED_SIZE, GL_TEXTURE_GREEN_SIZE,
    GL_TEXTURE_BLUE_SIZE, GL_TEXTURE_ALPHA_SIZE, GL_TEXTURE_LUMINANCE_SIZE,
    GL_TEXTURE_INTENSITY_SIZE
};

static void print_level(const char *what, GLenum target, GLint level)
{
    int i;
    printf("%s level %d i", what, (int)level);
    for (i = 0; i < 11; i++) {
        GLint v = -7, width = -7;
        glGetTexLevelParameteriv(target, level, GL_TEXTURE_WIDTH, &width);
        glGetTexLevelParameteriv(target, level, level_pnames[i], &v);
        /* An absent image's internal format differs (osmesa-differences.md 16). */
        if (width == 0 && level_pnames[i] == GL_TEXTURE_INTERNAL_FORMAT)
            continue;
        printf(" %d", (int)v);
    }
    printf(" %s\n", ffl_error_name(glGetError()));
}

static void print_bytes(const char *what, const GLubyte *b, int n)
{
    int i;
    printf("%s ub", what);
    for (i = 0; i < n; i++)
        printf(" %d", (int)b[i]);
    printf("\n");
}

static void print_image_floats(const char *what, GLenum target, GLint level, GLenum format, int n)
{
    GLfloat f[256];
    int i;
    for (i = 0; i < 256; i++)
        f[i] = -7.0f;
    glGetTexImage(target, level, format, GL_FLOAT, f);
    printf("%s", what);
    ffl_pfv("f", f, n);
    printf(" %s\n", ffl_error_name(glGetError()));
}

int main(void)
{
    GLubyte rgba[4 * 4 * 4], out[512];
    GLushort shorts[4 * 4];
    GLfloat floats[2 * 2 * 4];
    GLubyte padded[64];
    GLuint tex;
    int i;

    ffl_test_init();
    glViewport(0, 0, 64, 64);
    for (i = 0; i < 64; i++)
        rgba[i] = (GLubyte)(i * 4 + 1);
    for (i = 0; i < 16; i++)
        shorts[i] = (GLushort)(i * 4099 + 17);
    for (i = 0; i < 16; i++)
        floats[i] = (GLfloat)i / 15.0f - 0.2f;
    for (i = 0; i < 64; i++)
        padded[i] = (GLubyte)(255 - i * 3);

    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    print_level("absent 2d", GL_TEXTURE_2D, 0);

    /* RGBA8 from unsigned bytes, read as bytes in RGBA, BGRA, RGB, ALPHA, LUMINANCE. */
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    ffl_print_error("rgba8");
    print_level("rgba8", GL_TEXTURE_2D, 0);
    memset(out, 0, sizeof out);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out);
    print_bytes("rgba8 as rgba", out, 64);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_BGRA, GL_UNSIGNED_BYTE, out);
    print_bytes("rgba8 as bgra", out, 64);
    memset(out, 0, sizeof out);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGB, GL_UNSIGNED_BYTE, out);
    print_bytes("rgba8 as rgb", out, 48);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_ALPHA, GL_UNSIGNED_BYTE, out);
    print_bytes("rgba8 as alpha", out, 16);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_UNSIGNED_SHORT, GL_UNSIGNED_BYTE, out);
    ffl_print_error("get bad format");
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_SHORT_5_6_5, out);
    ffl_print_error("get packed mismatch");
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4, out);
    print_bytes("rgba8 as 4444", out, 32);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_BGRA, GL_UNSIGNED_INT_8_8_8_8_REV, out);
    print_bytes("rgba8 as bgra 8888rev", out, 64);
    print_image_floats("rgba8 floats", GL_TEXTURE_2D, 0, GL_RGBA, 64);

    /* Pack modes: alignment 8, row length 6, skips, swap bytes. */
    glPixelStorei(GL_PACK_ALIGNMENT, 8);
    glPixelStorei(GL_PACK_ROW_LENGTH, 5);
    glPixelStorei(GL_PACK_SKIP_ROWS, 1);
    glPixelStorei(GL_PACK_SKIP_PIXELS, 2);
    memset(out, 0xAA, sizeof out);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGB, GL_UNSIGNED_BYTE, out);
    print_bytes("packed rgb", out, 150);
    glPixelStorei(GL_PACK_SWAP_BYTES, 1);
    glPixelStorei(GL_PACK_ROW_LENGTH, 0);
    glPixelStorei(GL_PACK_SKIP_ROWS, 0);
    glPixelStorei(GL_PACK_SKIP_PIXELS, 0);
    memset(out, 0, sizeof out);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_LUMINANCE_ALPHA, GL_UNSIGNED_SHORT, out);
    print_bytes("swapped la shorts", out, 64);
    glPixelStorei(GL_PACK_SWAP_BYTES, 0);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);

    /* Unpack modes: a 3 x 2 region of a padded image, rows of 5 pixels, alignment 2. */
    glPixelStorei(GL_UNPACK_ALIGNMENT, 2);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 5);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 1);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 1);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 1, 2, 3, 2, GL_RGB, GL_UNSIGNED_BYTE, padded);
    ffl_print_error("sub rgb");
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out);
    print_bytes("after sub", out, 64);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 3, 3, 2, 1, GL_RGB, GL_UNSIGNED_BYTE, padded);
    ffl_print_error("sub outside");
    glTexSubImage2D(GL_TEXTURE_2D, 1, 0, 0, 1, 1, GL_RGB, GL_UNSIGNED_BYTE, padded);
    ffl_print_error("sub absent level");
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, floats);
    ffl_print_error("sub depth into color");

    /* Luminance-alpha from swapped shorts; intensity and alpha from floats (clamped). */
    glPixelStorei(GL_UNPACK_SWAP_BYTES, 1);
    glTexImage2D(GL_TEXTURE_2D, 1, GL_LUMINANCE8_ALPHA8, 2, 2, 0, GL_LUMINANCE_ALPHA,
                 GL_UNSIGNED_SHORT, shorts);
    glPixelStorei(GL_UNPACK_SWAP_BYTES, 0);
    ffl_print_error("la8 shorts");
    print_level("la8", GL_TEXTURE_2D, 1);
    print_image_floats("la8 as rgba", GL_TEXTURE_2D, 1, GL_RGBA, 16);
    print_image_floats("la8 as la", GL_TEXTURE_2D, 1, GL_LUMINANCE_ALPHA, 8);
    glTexImage2D(GL_TEXTURE_2D, 2, GL_INTENSITY16, 1, 1, 0, GL_RGBA, GL_FLOAT, floats + 4);
    print_level("intensity16", GL_TEXTURE_2D, 2);
    print_image_floats("intensity16 as rgba", GL_TEXTURE_2D, 2, GL_RGBA, 4);
    glTexImage2D(GL_TEXTURE_2D, 2, GL_ALPHA8, 1, 1, 0, GL_RGBA, GL_FLOAT, floats + 12);
    print_image_floats("alpha8 as rgba", GL_TEXTURE_2D, 2, GL_RGBA, 4);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, 2, 2, 0, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, shorts);
    print_image_floats("rgb8 from 565", GL_TEXTURE_2D, 0, GL_RGB, 12);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 2, 2, 0, GL_BGRA, GL_UNSIGNED_SHORT_1_5_5_5_REV,
                 shorts);
    print_image_floats("rgba8 from bgra 1555rev", GL_TEXTURE_2D, 0, GL_RGBA, 16);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16, 2, 2, 0, GL_RGBA, GL_UNSIGNED_SHORT, shorts);
    print_image_floats("rgba16 from shorts", GL_TEXTURE_2D, 0, GL_RGBA, 16);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_SHORT, out);
    print_bytes("rgba16 as shorts", out, 32);

    /* Pixel transfer applies when unpacking. */
    glPixelTransferf(GL_RED_SCALE, 0.75f);
    glPixelTransferf(GL_GREEN_BIAS, 0.25f);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    glPixelTransferf(GL_RED_SCALE, 1.0f);
    glPixelTransferf(GL_GREEN_BIAS, 0.0f);
    print_image_floats("transferred", GL_TEXTURE_2D, 0, GL_RGBA, 16);

    /* 1D, 3D with image height and skip images, cube faces, depth. */
    glBindTexture(GL_TEXTURE_1D, 0);
    glTexImage1D(GL_TEXTURE_1D, 0, GL_RGB8, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    print_level("1d", GL_TEXTURE_1D, 0);
    print_image_floats("1d", GL_TEXTURE_1D, 0, GL_RGB, 12);
    glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, 3);
    glPixelStorei(GL_UNPACK_SKIP_IMAGES, 1);
    glTexImage3D(GL_TEXTURE_3D, 0, GL_LUMINANCE8, 2, 2, 2, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE,
                 padded);
    glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, 0);
    glPixelStorei(GL_UNPACK_SKIP_IMAGES, 0);
    ffl_print_error("3d");
    print_level("3d", GL_TEXTURE_3D, 0);
    print_image_floats("3d", GL_TEXTURE_3D, 0, GL_LUMINANCE, 8);
    glTexImage2D(GL_TEXTURE_CUBE_MAP_NEGATIVE_Y, 0, GL_RGBA8, 2, 2, 0, GL_RGBA,
                 GL_UNSIGNED_BYTE, rgba);
    print_level("cube -y", GL_TEXTURE_CUBE_MAP_NEGATIVE_Y, 0);
    print_level("cube +y", GL_TEXTURE_CUBE_MAP_POSITIVE_Y, 0);
    glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X, 0, GL_RGBA8, 2, 4, 0, GL_RGBA,
                 GL_UNSIGNED_BYTE, rgba);
    ffl_print_error("cube not square");
    glTexImage2D(GL_TEXTURE_CUBE_MAP, 0, GL_RGBA8, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    ffl_print_error("cube map target");
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, 2, 2, 0, GL_DEPTH_COMPONENT,
                 GL_FLOAT, floats);
    ffl_print_error("depth");
    print_image_floats("depth", GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 4);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, out);
    ffl_print_error("depth as rgba");
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 2, 2, 0, GL_DEPTH_COMPONENT, GL_FLOAT, floats);
    ffl_print_error("depth data into color");

    /* Proxies. */
    glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA8, 66, 34, 1, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    print_level("proxy 66x34 border", GL_PROXY_TEXTURE_2D, 0);
    glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA8, 1 << 20, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 NULL);
    ffl_print_error("proxy too big");
    print_level("proxy too big", GL_PROXY_TEXTURE_2D, 0);
    glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA8, -1, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    ffl_print_error("proxy negative");

    /* Generated mipmaps. */
    glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 4, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    print_level("mipmap", GL_TEXTURE_2D, 1);
    print_level("mipmap", GL_TEXTURE_2D, 2);
    print_level("mipmap", GL_TEXTURE_2D, 3);
    glGetTexImage(GL_TEXTURE_2D, 2, GL_RGBA, GL_UNSIGNED_BYTE, out);
    print_bytes("mipmap 2", out, 4);

    /* Errors: every one leaves the image as it was. */
    glTexImage2D(0x1234, 0, GL_RGBA8, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    ffl_print_error("target");
    glTexImage2D(GL_TEXTURE_2D, -1, GL_RGBA8, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    ffl_print_error("level negative");
    glTexImage2D(GL_TEXTURE_2D, 40, GL_RGBA8, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    ffl_print_error("level 40");
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 2, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    ffl_print_error("border 2");
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, -2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    ffl_print_error("width negative");
    glTexImage2D(GL_TEXTURE_2D, 0, 0x1234, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    ffl_print_error("internal format");
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 2, 2, 0, 0x1234, GL_UNSIGNED_BYTE, rgba);
    ffl_print_error("format");
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 2, 2, 0, GL_RGBA, 0x1234, rgba);
    ffl_print_error("type");
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 2, 2, 0, GL_RGBA, GL_BITMAP, rgba);
    ffl_print_error("bitmap");
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 2, 2, 0, GL_RGB, GL_UNSIGNED_SHORT_4_4_4_4, rgba);
    ffl_print_error("packed mismatch");
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1 << 15, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    ffl_print_error("too wide");
    glTexImage1D(GL_TEXTURE_2D, 0, GL_RGBA8, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    ffl_print_error("1d on 2d target");
    glTexImage3D(GL_TEXTURE_3D, 0, GL_DEPTH_COMPONENT, 2, 2, 2, 0, GL_DEPTH_COMPONENT,
                 GL_FLOAT, floats);
    ffl_print_error("3d depth");
    glGetTexImage(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out);
    ffl_print_error("get proxy");
    glGetTexImage(GL_TEXTURE_2D, -1, GL_RGBA, GL_UNSIGNED_BYTE, out);
    ffl_print_error("get level negative");
    glGetTexLevelParameteriv(GL_TEXTURE_CUBE_MAP, 0, GL_TEXTURE_WIDTH, (GLint *)out);
    ffl_print_error("level param cube map");
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_PRIORITY, (GLint *)out);
    ffl_print_error("level param pname");
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSED, (GLint *)out);
    printf("compressed %d %s\n", (int)((GLint *)out)[0], ffl_error_name(glGetError()));
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSED_IMAGE_SIZE, (GLint *)out);
    ffl_print_error("compressed size");
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, 64, rgba);
    ffl_print_error("compressed image of rgba");
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 2, 2, GL_RGBA, 16, rgba);
    ffl_print_error("compressed sub rgba");
    glGetCompressedTexImage(GL_TEXTURE_2D, 0, out);
    ffl_print_error("get compressed");
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 3, 0, 0, 0, 2, 2);
    ffl_print_error("copy sub outside");
    glBegin(GL_POINTS);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    glEnd();
    ffl_print_error("in begin");
    print_level("after errors", GL_TEXTURE_2D, 0);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out);
    print_bytes("after errors", out, 32);
    return 0;
}
