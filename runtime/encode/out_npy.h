/* NumPy .npy files of float images (spec/outputs.md "Float outputs"):
 * what numpy.save writes for a float32 array, so numpy.load (with
 * allow_pickle=False) reads the pixels back bit for bit.  One encoder for
 * every float output (depth, disparity, a pfm image, and later normals
 * and flow). */
#ifndef GLS_OUT_NPY_H
#define GLS_OUT_NPY_H

#include <stdint.h>
#include "buf.h"

/* Format version 1.0, dtype '<f4', fortran_order False, shape (h, w) for
 * channels 1, (h, w, channels) otherwise; v is top row first, channels
 * interleaved, and is stored in that order (C order).  The header dict is
 * padded with spaces and ends in '\n' so the data starts at a multiple of
 * 64 bytes, as numpy writes it.  0, or -1 when out of memory. */
int gls_encode_npy(const float *v, uint32_t w, uint32_t h, unsigned channels, gls_buf *out);

#endif
