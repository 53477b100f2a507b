/* Host driver for the column example's record reading: reads a count and
 * that many 64-bit hex words (a frame's output beats) on stdin, gives them
 * to fcc_read_records and prints what it returns after its own lines. The
 * example's own main is renamed so that this one runs. */
#include <stdio.h>
#include <stdlib.h>
#define main fcc_example_main
#include FCC_EXAMPLE
#undef main

int main(void)
{
    unsigned long long word;
    unsigned n, i;
    uint64_t *w;
    if (scanf("%u", &n) != 1) {
        return 2;
    }
    w = calloc(n + 1u, sizeof *w);
    if (w == NULL) {
        return 2;
    }
    for (i = 0; i < n; i++) {
        if (scanf("%llx", &word) != 1) {
            return 2;
        }
        w[i] = (uint64_t)word;
    }
    printf("returned %d\n", fcc_read_records(w, n));
    free(w);
    return 0;
}
