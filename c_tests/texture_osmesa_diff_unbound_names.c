/* ffl-test: osmesa-diff */
/*
 * OSMesa vs the spec: texture names and limits of GL 1.5.
 *
 * - A name glGenTextures returned names no texture until it is bound (§3.8.12): GL 1.5
 *   glAreTexturesResident gives GL_INVALID_VALUE for it. Mesa makes an object at
 *   glGenTextures and calls it resident.
 * - GL_TEXTUREi past GL_MAX_TEXTURE_UNITS - 1 is GL_INVALID_ENUM for glActiveTexture (§2.7).
 *   OSMesa's GL_MAX_TEXTURE_UNITS is 8 too, but it takes units up to its 32 image units.
 * - glGetTexLevelParameter of an image never specified: internal format 1 (table 6.17);
 *   Mesa's GL 3.0+ context gives GL_RGBA.
 * - A texture size that is not a power of two (plus the border) is GL_INVALID_VALUE in
 *   GL 1.5 (§3.8.1); Mesa takes it (ARB_texture_non_power_of_two).
 * - glCopyTexImage2D with internal format 3: GL_INVALID_VALUE (§3.8.2); Mesa: INVALID_ENUM.
 * - glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_RGB, GL_ONE) is GL_INVALID_ENUM (table 3.20);
 *   Mesa takes GL_ZERO and GL_ONE (ATI_texture_env_combine3).
 */
#include "ffl_test.h"

int main(void)
{
    GLuint names[2];
    GLboolean residences[2] = { 7, 7 };
    GLint value = -7;

    ffl_test_init();
    glViewport(0, 0, 64, 64);
    glGenTextures(2, names);
    glBindTexture(GL_TEXTURE_2D, names[0]);
    printf("resident_unbound result %d", (int)glAreTexturesResident(2, names, residences));
    printf(" error_code %d ref result 0 error_code %d\n", (int)glGetError(),
           (int)GL_INVALID_VALUE);

    glActiveTexture(GL_TEXTURE0 + 8);
    printf("active_unit_8 error_code %d ref error_code %d\n", (int)glGetError(),
           (int)GL_INVALID_ENUM);
    glActiveTexture(GL_TEXTURE0);

    glGetTexLevelParameteriv(GL_TEXTURE_2D, 3, GL_TEXTURE_INTERNAL_FORMAT, &value);
    printf("absent_image internal_format %d ref internal_format 1\n", (int)value);

    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 3, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    printf("npot_width error_code %d ref error_code %d\n", (int)glGetError(),
           (int)GL_INVALID_VALUE);

    glCopyTexImage2D(GL_TEXTURE_2D, 0, 3, 0, 0, 2, 2, 0);
    printf("copy_internal_3 error_code %d ref error_code %d\n", (int)glGetError(),
           (int)GL_INVALID_VALUE);

    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_RGB, GL_ONE);
    printf("source_one error_code %d ref error_code %d\n", (int)glGetError(),
           (int)GL_INVALID_ENUM);
    return 0;
}
