/* The image decoders behind texture.c: JPEG through libjpeg-turbo
 * (texture_jpeg.c), PNG, TGA and BMP through stb_image compiled into
 * glscene with only those formats (texture_stb.c).  Each returns RGBA8,
 * row 0 at the top, in memory from malloc; on failure NULL (or -1) and the
 * decoder's reason in why. */
#ifndef GLS_TEXTURE_CODECS_H
#define GLS_TEXTURE_CODECS_H
#include <stddef.h>

/* the file is a JPEG, or a damaged one, by its first bytes */
int gls_jpeg_is(const unsigned char *data, size_t len);
/* the size from the header, before anything is decoded */
int gls_jpeg_info(const unsigned char *data, size_t len, int *w, int *h, char *why, size_t whylen);
unsigned char *gls_jpeg_load_rgba(const unsigned char *data, size_t len, int *w, int *h, char *why, size_t whylen);

int gls_stb_info(const unsigned char *data, size_t len, int *w, int *h, char *why, size_t whylen);
unsigned char *gls_stb_load_rgba(const unsigned char *data, size_t len, int *w, int *h, char *why, size_t whylen);

#endif
