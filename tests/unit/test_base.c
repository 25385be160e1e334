/* The base layer's helpers (base/): growth, whole-file reading, the caret
 * excerpt, the tokenizer, number reading, vector and matrix operations,
 * mkdir -p, atomic writes and the fixed-set option message.  Each is used by several layers; the tools'
 * tests check them through their messages, these check the helpers
 * themselves, including the cases no tool's input reaches easily. */
#include <dirent.h>
#include <errno.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>
#include "atomic_write.h"
#include "buf.h"
#include "check.h"
#include "choice.h"
#include "mkdirs.h"
#include "numfmt.h"
#include "readfile.h"
#include "srcline.h"
#include "textfile.h"
#include "vec.h"

static char dir[] = "/tmp/gls_test_base_XXXXXX";

static void write_file(const char *path, const char *data, size_t n)
{
    FILE *f = fopen(path, "wb");
    if (f) {
        fwrite(data, 1, n, f);
        fclose(f);
    }
}

static void test_grow(void)
{
    CHECK(gls_grow_cap(0, 1, 8) == 32);         /* 16 elements and 256 bytes at least */
    CHECK(gls_grow_cap(0, 1, 1) == 256);
    CHECK(gls_grow_cap(0, 1, 1000) == 16);
    CHECK(gls_grow_cap(32, 20, 8) == 32);       /* it fits: unchanged */
    CHECK(gls_grow_cap(32, 33, 8) == 64);
    CHECK(gls_grow_cap(32, 1000, 8) == 1024);
    CHECK(gls_grow_cap(0, SIZE_MAX / 4, 8) == 0); /* more bytes than a size_t holds */
    CHECK(gls_resize(NULL, SIZE_MAX / 2, 4) == NULL);
    int *a = NULL;
    size_t cap = 0;
    for (int i = 0; i < 1000; i++) {
        if (gls_grow(&a, &cap, (size_t)i + 1, sizeof *a))
            break;
        a[i] = i;
    }
    CHECK(cap == 1024);
    CHECK(a && a[999] == 999 && a[17] == 17);
    /* a failed growth leaves the array and its capacity as they were */
    int *before = a;
    CHECK(gls_grow(&a, &cap, SIZE_MAX / 2, sizeof *a) == -1);
    CHECK(a == before && cap == 1024);
    free(a);
    gls_buf b = {0};
    for (int i = 0; i < 100; i++)
        CHECK(gls_buf_put(&b, "abc", 3) == 0);
    CHECK(b.len == 300 && b.cap >= 300 && memcmp(b.data + 297, "abc", 3) == 0);
    CHECK(gls_buf_reserve(&b, SIZE_MAX) == -1 && b.len == 300);
    free(b.data);
}

static void test_readfile(void)
{
    char path[128], sub[128];
    size_t len = 99;
    gls_read_error e;
    snprintf(path, sizeof path, "%s/f.txt", dir);
    write_file(path, "hello\nworld", 11);
    char *t = gls_file_read(path, 100, &len, &e);
    CHECK(t && len == 11 && memcmp(t, "hello\nworld", 12) == 0); /* and the NUL */
    free(t);
    /* a file over the limit is refused before reading, with its size */
    CHECK(!gls_file_read(path, 10, &len, &e) && e.status == GLS_READ_TOO_LARGE && e.size == 11);
    t = gls_file_read(path, 11, &len, &e); /* exactly the limit */
    CHECK(t && len == 11);
    free(t);
    snprintf(sub, sizeof sub, "%s/empty", dir);
    write_file(sub, "", 0);
    t = gls_file_read(sub, 10, &len, &e);
    CHECK(t && len == 0 && t[0] == 0);
    free(t);
    CHECK(!gls_file_read(dir, 100, &len, &e) && e.status == GLS_READ_DIR);
    snprintf(sub, sizeof sub, "%s/missing", dir);
    CHECK(!gls_file_read(sub, 100, &len, &e) && e.status == GLS_READ_OPEN && e.err == ENOENT);
    /* only regular files: a device, and a FIFO with no writer (opening it
       must not wait: alarm ends a regression with SIGALRM instead of a hang) */
    CHECK(!gls_file_read("/dev/zero", 1000, &len, &e) && e.status == GLS_READ_NOT_REGULAR && S_ISCHR(e.mode));
    CHECK(!gls_file_read("/dev/null", 1000, &len, &e) && e.status == GLS_READ_NOT_REGULAR);
    char fifo[128];
    snprintf(fifo, sizeof fifo, "%s/fifo", dir);
    CHECK(mkfifo(fifo, 0600) == 0);
    struct stat st;
    alarm(10);
    CHECK(gls_file_open(fifo, &st, &e) == -1 && e.status == GLS_READ_NOT_REGULAR && S_ISFIFO(e.mode));
    CHECK_STR(gls_file_kind(e.mode), "it is a FIFO (named pipe), not a regular file");
    CHECK(gls_file_kind(S_IFREG) == NULL);
    CHECK(gls_is_file(fifo)); /* there, so not "no such file": reading says what it is */
    alarm(0);
    unlink(fifo);
    CHECK(gls_is_dir(dir) && !gls_is_file(dir) && gls_is_file(path) && !gls_is_dir(path) && !gls_is_file(sub));
}

/* The excerpt as a string, or "(none)". */
static const char *excerpt(const char *text, unsigned line, unsigned col, gls_excerpt_style style, size_t len)
{
    static char out[1024];
    gls_buf b = {0};
    if (gls_excerpt(&b, text, len ? len : strlen(text), line, col, style) || b.len >= sizeof out)
        snprintf(out, sizeof out, "(none)");
    else
        memcpy(out, b.data, b.len), out[b.len] = 0;
    free(b.data);
    return out;
}

static void test_excerpt(void)
{
    CHECK_STR(excerpt("ab\n\tcd e\n", 2, 4, GLS_EXCERPT_WHOLE_LINE, 0), "\tcd e\n\t  ^");
    CHECK_STR(excerpt("ab\r\ncd", 1, 2, GLS_EXCERPT_WHOLE_LINE, 0), "ab\n ^");
    CHECK_STR(excerpt("ab\ncd\n", 3, 1, GLS_EXCERPT_WINDOW, 0), "\n^"); /* after the last newline */
    CHECK_STR(excerpt("ab\ncd", 3, 1, GLS_EXCERPT_WHOLE_LINE, 0), "(none)");
    /* a NUL byte: the compiler's caret goes past it, a text input's line ends there */
    CHECK_STR(excerpt("ab\0cd x;", 1, 7, GLS_EXCERPT_WHOLE_LINE, 8), "ab\n      ^");
    CHECK_STR(excerpt("ab\0cd x;", 1, 7, GLS_EXCERPT_WINDOW, 8), "ab\n  ^");
    /* a long line: whole for the compiler, a 160-byte window for text inputs */
    char line[301];
    for (int i = 0; i < 300; i++)
        line[i] = (char)('a' + i % 26);
    line[300] = 0;
    CHECK(strlen(excerpt(line, 1, 150, GLS_EXCERPT_WHOLE_LINE, 0)) == 300 + 1 + 149 + 1);
    const char *w = excerpt(line, 1, 150, GLS_EXCERPT_WINDOW, 0);
    CHECK(strncmp(w, "...", 3) == 0 && strncmp(w + 3, line + 69, 160) == 0 && strncmp(w + 163, "...\n   ", 7) == 0);
    CHECK(strlen(w) == 3 + 160 + 3 + 1 + 3 + 80 + 1);
    /* the message form, and nothing appended when it does not fit */
    char msg[64];
    gls_text_error(msg, sizeof msg, "key 1,5\n", 8, "f.cam", 1, 6, "a comma in '%s'", "1,5");
    CHECK_STR(msg, "f.cam:1:6: error: a comma in '1,5'\nkey 1,5\n     ^");
    gls_text_error(msg, 40, "key 1,5\n", 8, "f.cam", 1, 6, "a comma in '%s'", "1,5");
    CHECK_STR(msg, "f.cam:1:6: error: a comma in '1,5'");
}

static void test_split(void)
{
    char line[] = "  R 1\t2 # 3 4";
    char *tok[4];
    CHECK(gls_text_split(line, "#", " \t", tok, 4) == 3);
    CHECK_STR(tok[0], "R");
    CHECK(tok[2] - line + 1 == 7); /* the column of "2" */
    char l2[] = "a b c d e";
    CHECK(gls_text_split(l2, "#", " ", tok, 4) == 4); /* "more than 3" */
    char l3[] = "w 640\rx";
    CHECK(gls_text_split(l3, "#\r", " ", tok, 4) == 2);
    char l4[] = "# only a comment";
    CHECK(gls_text_split(l4, "#", " ", tok, 4) == 0);
}

static void test_numbers(void)
{
    double v = 7;
    CHECK(gls_parse_double("1.5e3", &v) == NULL && v == 1500);
    CHECK_STR(gls_parse_double("1e400", &v), "is too large for a double (magnitudes up to 1.8e308)");
    CHECK_STR(gls_parse_double("1e-400", &v), "is too close to zero for a double (nonzero magnitudes from 2.2e-308)");
    CHECK_STR(gls_parse_double("nan", &v), "is not a finite number");
    CHECK_STR(gls_parse_double("1,5", &v), "is not a finite number");
    CHECK(v == 1500); /* untouched by the failures */
    CHECK(gls_parse_finite("1e-400", &v) == NULL && v == 0);
    CHECK_STR(gls_parse_finite("1e400", &v), "is not a finite number");
    CHECK_STR(gls_parse_finite("", &v), "is not a finite number");
    char buf[40];
    gls_fmt_double(buf, sizeof buf, 0.1);
    CHECK_STR(buf, "0.1");
    gls_fmt_double(buf, sizeof buf, 1500);
    CHECK_STR(buf, "1500");
    gls_fmt_float(buf, sizeof buf, 0.1f);
    CHECK_STR(buf, "0.1");
}

static void test_vec(void)
{
    const double A[9] = {1, 2, 3, 4, 5, 6, 7, 8, 10}, B[9] = {0, 1, 0, -1, 0, 0, 0, 0, 1};
    double C[9], T[9];
    rm_mul(A, B, C);
    const double AB[9] = {-2, 1, 3, -5, 4, 6, -8, 7, 10};
    CHECK(memcmp(C, AB, sizeof C) == 0);
    rm_transpose(A, T);
    CHECK(T[1] == 4 && T[2] == 7 && T[5] == 8);
    CHECK(rm_det(A) == -3);
    rv3 v = rm_apply(A, rv(1, 0, -1)), u = rm_apply_t(A, rv(1, 0, -1));
    CHECK(v.x == -2 && v.y == -2 && v.z == -3);
    CHECK(u.x == -6 && u.y == -6 && u.z == -7);
    double M[16] = {1, 0, 0, 5, 0, 1, 0, 6, 0, 0, 1, 7, 0, 0, 0, 1}, N[16], h[4];
    m4_mul(M, M, N); /* two translations */
    CHECK(N[3] == 10 && N[7] == 12 && N[11] == 14 && N[15] == 1);
    m4_apply(N, 1, 2, 3, 1, h);
    CHECK(h[0] == 11 && h[1] == 14 && h[2] == 17 && h[3] == 1);
}

static void test_files(void)
{
    char p[160];
    snprintf(p, sizeof p, "%s/a/b//c", dir);
    CHECK(gls_mkdir_p(p) == 0 && gls_is_dir(p));
    CHECK(gls_mkdir_p(p) == 0); /* exists: fine */
    snprintf(p, sizeof p, "%s/a/b/c/out.bin", dir);
    CHECK(gls_write_file_atomic(p, "xyz", 3) == 0);
    size_t len;
    gls_read_error e;
    char *t = gls_file_read(p, 10, &len, &e);
    CHECK(t && len == 3 && memcmp(t, "xyz", 3) == 0);
    free(t);
    snprintf(p, sizeof p, "%s/a/b/c/out.bin/d", dir);
    CHECK(gls_mkdir_p(p) == -1 && errno == ENOTDIR);
    snprintf(p, sizeof p, "%s/a", dir);
    CHECK(gls_write_file_atomic(p, "x", 1) == -1 && errno == EEXIST);
    CHECK_STR(gls_write_error(p, EEXIST), "it is a directory");
    CHECK_STR(gls_write_error("/dev/null", EEXIST), "it is a character device, not a regular file");
}

/* The file at path, as a string ("" when empty, NULL when absent). */
static char *slurp(const char *path)
{
    size_t len;
    gls_read_error e;
    return gls_file_read(path, 1 << 20, &len, &e);
}

/* The names in directory d other than . and .., space-separated (for
 * messages: what a writer left behind). */
static void list_dir(const char *d, char *out, size_t cap)
{
    out[0] = 0;
    DIR *dp = opendir(d);
    if (!dp)
        return;
    for (struct dirent *e; (e = readdir(dp));)
        if (strcmp(e->d_name, ".") && strcmp(e->d_name, "..") && strlen(out) + strlen(e->d_name) + 2 < cap)
            strcat(strcat(out, out[0] ? " " : ""), e->d_name);
    closedir(dp);
}

/* Write to a temporary, then rename (base/atomic_write.c): until the
 * commit the target keeps its old content (or does not exist), and the
 * temporary is a file beside it, in its directory; after the commit the
 * target has the new content and the temporary is gone; an abort leaves
 * the directory as it was.  A writer that wrote in place fails the first
 * check, one that wrote its temporary elsewhere (another file system: the
 * rename would fail, or copy) the second. */
static void test_atomic_steps(void)
{
    char d[160], p[200], left[512];
    snprintf(d, sizeof d, "%s/atomic", dir);
    CHECK(gls_mkdir_p(d) == 0);
    snprintf(p, sizeof p, "%s/out.txt", d);
    write_file(p, "old", 3);

    gls_atomic_file f;
    CHECK(gls_atomic_begin(&f, p) == 0);
    char *t = slurp(p);
    CHECK_MSG(t && strcmp(t, "old") == 0, "after begin the target holds '%s'", t ? t : "(none)");
    free(t);
    CHECK(write(f.fd, "new!", 4) == 4);
    t = slurp(p);
    CHECK_MSG(t && strcmp(t, "old") == 0, "before the commit the target holds '%s'", t ? t : "(none)");
    free(t);
    /* the temporary: another name, in the target's directory */
    const char *slash = f.tmp ? strrchr(f.tmp, '/') : NULL;
    CHECK_MSG(f.tmp && strcmp(f.tmp, p) != 0 && slash && (size_t)(slash - f.tmp) == strlen(d) &&
                  strncmp(f.tmp, d, strlen(d)) == 0,
              "temporary '%s' for '%s'", f.tmp ? f.tmp : "(none)", p);
    struct stat st;
    CHECK(f.tmp && stat(f.tmp, &st) == 0 && S_ISREG(st.st_mode) && st.st_size == 4);
    CHECK(gls_atomic_commit(&f) == 0);
    t = slurp(p);
    CHECK_MSG(t && strcmp(t, "new!") == 0, "after the commit the target holds '%s'", t ? t : "(none)");
    free(t);
    list_dir(d, left, sizeof left);
    CHECK_STR(left, "out.txt");

    /* abort: an existing target unchanged, a new one never appears */
    CHECK(gls_atomic_begin(&f, p) == 0);
    CHECK(write(f.fd, "abandoned", 9) == 9);
    gls_atomic_abort(&f);
    t = slurp(p);
    CHECK_MSG(t && strcmp(t, "new!") == 0, "after an abort the target holds '%s'", t ? t : "(none)");
    free(t);
    snprintf(p, sizeof p, "%s/new.txt", d);
    CHECK(gls_atomic_begin(&f, p) == 0);
    CHECK(access(p, F_OK) != 0); /* not there until the commit */
    CHECK(write(f.fd, "x", 1) == 1);
    gls_atomic_abort(&f);
    CHECK(access(p, F_OK) != 0);
    list_dir(d, left, sizeof left);
    CHECK_STR(left, "out.txt");
}

/* gls_write_file_atomic whose write fails half-way (a file size limit:
 * the temporary gets 4096 of the 65536 bytes): the target keeps its old
 * content and nothing else is left in the directory. */
static void test_atomic_failed_write(void)
{
    char d[160], p[200], left[512];
    snprintf(d, sizeof d, "%s/atomic_fail", dir);
    CHECK(gls_mkdir_p(d) == 0);
    snprintf(p, sizeof p, "%s/out.bin", d);
    write_file(p, "old", 3);
    static char big[65536];
    memset(big, 'n', sizeof big);
    struct rlimit old, lim;
    CHECK(getrlimit(RLIMIT_FSIZE, &old) == 0);
    lim = old;
    lim.rlim_cur = 4096;
    void (*was)(int) = signal(SIGXFSZ, SIG_IGN); /* EFBIG rather than the signal */
    CHECK(setrlimit(RLIMIT_FSIZE, &lim) == 0);
    int r = gls_write_file_atomic(p, big, sizeof big), e = errno;
    setrlimit(RLIMIT_FSIZE, &old);
    signal(SIGXFSZ, was);
    CHECK_MSG(r == -1 && e == EFBIG, "returned %d, errno %d", r, e);
    char *t = slurp(p);
    CHECK_MSG(t && strcmp(t, "old") == 0, "the target holds %zu bytes", t ? strlen(t) : 0);
    free(t);
    list_dir(d, left, sizeof left);
    CHECK_STR(left, "out.bin");
}

/* gls_mkdir_p_made says what it made, and gls_rmdir_made takes back only
   that, only while empty: the directory there before stays, and so does
   one that holds a file (with its parents). */
static void test_mkdir_made(void)
{
    char p[160], q[160];
    size_t made, before = strlen(dir);
    snprintf(p, sizeof p, "%s/m", dir);
    CHECK(gls_mkdir_p(p) == 0);
    snprintf(p, sizeof p, "%s/m/x//y/z", dir);
    CHECK(gls_mkdir_p_made(p, &made) == 0 && made == before + 4); /* ".../m/x" */
    gls_rmdir_made(p, made);
    snprintf(q, sizeof q, "%s/m", dir);
    CHECK(gls_is_dir(q));
    snprintf(q, sizeof q, "%s/m/x", dir);
    CHECK(!gls_is_dir(q));
    CHECK(gls_mkdir_p_made(p, &made) == 0 && made == before + 4);
    size_t again;
    CHECK(gls_mkdir_p_made(p, &again) == 0 && again == 0); /* all there: nothing made */
    snprintf(q, sizeof q, "%s/m/x//y/f", dir);
    CHECK(gls_write_file_atomic(q, "f", 1) == 0);
    gls_rmdir_made(p, made); /* z goes; y holds f, so y and x stay */
    CHECK(!gls_is_dir(p) && gls_is_file(q));
}

/* choice.h: found words, the message's three forms, a long value cut,
 * a message cut to the buffer (always terminated) */
static void test_choice(void)
{
    static const char *const w[] = {"lattice", "grid", "stratified"};
    char m[256];
    CHECK(gls_choice_find("grid", 4, w, 3) == 1);
    CHECK(gls_choice_find("gridx", 4, w, 3) == 1); /* a length, not a C string */
    CHECK(gls_choice_find("gri", 3, w, 3) == -1);
    gls_choice_message(m, sizeof m, "--pattern", 0, "gird", 4, w, 3);
    CHECK_STR(m, "--pattern takes one of: lattice, grid, stratified (not 'gird'); did you mean 'grid'?");
    gls_choice_message(m, sizeof m, "--pattern", 0, "hex", 3, w, 3);
    CHECK_STR(m, "--pattern takes one of: lattice, grid, stratified (not 'hex')");
    gls_choice_message(m, sizeof m, "--pattern", 0, NULL, 0, w, 3);
    CHECK_STR(m, "--pattern needs one of: lattice, grid, stratified");
    gls_choice_message(m, sizeof m, "--outputs", 1, "grdi,x", 4, w, 3);
    CHECK_STR(m, "--outputs takes a comma-separated list of: lattice, grid, stratified (not 'grdi'); did you mean 'grid'?");
    char big[300], want[400];
    memset(big, 'q', sizeof big);
    gls_choice_message(want, sizeof want, "-x", 0, big, sizeof big, w, 1);
    CHECK(strlen(want) == strlen("-x takes one of: lattice (not '...')") + 200);
    gls_choice_message(m, 10, "--pattern", 0, "gird", 4, w, 3);
    CHECK_STR(m, "--pattern");
}

int main(void)
{
    if (!mkdtemp(dir)) {
        printf("FAIL test_base: mkdtemp\n");
        return 1;
    }
    RUN(test_grow);
    RUN(test_readfile);
    RUN(test_excerpt);
    RUN(test_split);
    RUN(test_numbers);
    RUN(test_vec);
    RUN(test_files);
    RUN(test_atomic_steps);
    RUN(test_atomic_failed_write);
    RUN(test_mkdir_made);
    RUN(test_choice);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    if (system(cmd) != 0)
        printf("  could not remove %s\n", dir);
    CHECK_EXIT();
}
