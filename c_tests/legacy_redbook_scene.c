/* ffl-test: differential */
/*
 * examples/legacy/redbook_scene.c, a classic Red-Book-style program written against the
 * system <GL/gl.h> only, built unchanged against fflight and against OSMesa: its feedback
 * (display lists, attribute stacks, three lights, two-sided lighting, a texture, fog and
 * blending state) compared.
 */
#include "../examples/legacy/redbook_scene.c"
