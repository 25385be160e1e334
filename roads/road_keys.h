/* The keys of a road description (spec/road.md) as one table: each key's
 * values (type, range, destination), how often it may be given, what it
 * excludes, and its documentation.  road_parse.c parses, checks and words
 * every message from it, so that all keys report alike; road_keys_doc.c
 * writes the spec's key tables from it (glsroad --list-keys).  The table
 * and the keys' own steps (a point appended, a profile point added) are in
 * road_keys.c.  Internal to roads/. */
#ifndef GLS_ROAD_KEYS_H
#define GLS_ROAD_KEYS_H
#include <stddef.h>
#include "road.h"

/* The most words on one line (key included), and the most keys. */
#define ROAD_MAX_WORDS 64
#define ROAD_KEYS_MAX 64

/* What a value is. */
typedef enum {
    RV_RAW,   /* kept as text: the key's own step reads it         */
    RV_NUM,   /* a finite number (double), in a range              */
    RV_WHOLE, /* a whole number in lo..hi (int or long)            */
    RV_NAME,  /* a dotted scene name (demo.Tree), char[size]       */
    RV_IDENT, /* an identifier (letters, digits, '_'), char[size]  */
    RV_WORD,  /* one of words[] (int: its index)                   */
    RV_FLAG,  /* an option without a value: stores (int)lo         */
} road_vtype;

/* The range of an RV_NUM. */
typedef enum { RR_ANY, RR_POS, RR_NONNEG, RR_RANGE, RR_MIN } road_rtype;

typedef struct {
    road_vtype type;
    const char *what;         /* its name in messages ("lane width")            */
    road_rtype range;
    double lo, hi;            /* RR_RANGE: lo..hi, RR_MIN: >= lo; RV_WHOLE: lo..hi */
    const char *why;          /* said after the range in its message, or NULL   */
    const char *const *words; /* RV_WORD: the words, NULL-terminated            */
    size_t off, size;         /* destination: offset from the key's base and
                                 size of the field; size 0: not stored          */
    double def;               /* RV_NUM, RV_WHOLE stored into the description:
                                 the value before any line sets it              */
} road_val;

/* An option after a key's values: a word, alone (val.type RV_FLAG) or
 * followed by one value. */
typedef struct {
    const char *word;
    const char *arg; /* the value's name in messages ("S"), NULL for a flag */
    road_val val;
} road_opt;

/* A parsed value, as the key's own steps receive it. */
typedef union {
    double num;
    long whole;
    int word;
    const char *tok;
} road_value;

/* How often a key may be given: again with a later line replacing the
 * earlier (the default: what the parser has always done for a setting),
 * once (again is an error), any number of times (each line adds), or once
 * per its first value (a vehicle name: its step checks that). */
typedef enum { RK_LAST, RK_ONCE, RK_MANY, RK_KEYED } road_times;

/* The spec's table a key is listed in. */
typedef enum { RS_CURVE, RS_SECTION, RS_MOTION, RS_COUNT } road_section;

typedef struct road_pctx road_pctx; /* the parser's state (road_parse.c) */

typedef struct road_key road_key;
struct road_key {
    const char *key;
    road_section section;
    const char *values;  /* the values as messages and the spec show them      */
    const char *times;   /* the spec's "given" column where the kind of repeat
                            alone does not say it ("once per NAME"), or NULL */
    const char *deflt;   /* the spec's default column (Markdown); NULL: the
                            values' defaults                                   */
    const char *meaning; /* the spec's meaning column (Markdown)               */
    int min, max;        /* how many values; max -1: any (options follow)      */
    road_times repeat;
    const char *excludes; /* a key that may not be given with this one         */
    size_t line_off;      /* int field of road_desc for the key's line, or 0   */
    road_val val[4];      /* the values in order (what NULL: no more); values
                             past them are options, or else like the last one */
    const road_opt *opts; /* NULL, or ended by a NULL word                     */
    /* Before the values: checks and the base the values are stored at (an
       element of an array); NULL: the description.  Returns NULL after
       reporting an error through road_fail. */
    void *(*prepare)(road_pctx *c, road_desc *d, char **a, int na);
    /* After the values: what is not a plain store.  0, or -1 (reported). */
    int (*finish)(road_pctx *c, road_desc *d, void *base, char **a, int na, const road_value *v);
};

extern const road_key road_keys[];
extern const size_t road_nkeys;

/* ---- parser services for the keys' steps (road_parse.c) ----------------- */

/* Report an error at word tok of the line (NULL: at its key).  Returns -1. */
int road_fail(road_pctx *c, const char *tok, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
/* The line being parsed. */
int road_line(const road_pctx *c);
/* Parse word tok as value v of key (messages name both): 0, or -1. */
int road_value_parse(road_pctx *c, const char *key, const road_val *v, const char *tok, road_value *out);
/* "'WHAT' given twice (first on line FIRST)" at the key.  Returns -1. */
int road_twice(road_pctx *c, const char *what, int first);
/* Append (x, v) to profile p: increasing x from 0, at most
   ROAD_MAX_PROFILE_POINTS.  0, or -1 (reported). */
int road_profile_add(road_pctx *c, road_profile *p, double x, double v);
#endif
