/* Host driver for the example's packing: reads lines of three 64-bit hex
 * words, the IEEE bits of x, y and z, on stdin and prints each packed input
 * word in hex. The example's own main is renamed so that this one runs. */
#include <stdio.h>
#include <string.h>
#define main fcc_example_main
#include FCC_EXAMPLE
#undef main

int main(void)
{
    unsigned long long bits[3];
    double v[3];
    int i;
    while (scanf("%llx %llx %llx", &bits[0], &bits[1], &bits[2]) == 3) {
        for (i = 0; i < 3; i++) {
            memcpy(&v[i], &bits[i], sizeof v[i]);
        }
        printf("%016llx\n", (unsigned long long)fcc_pack_pixel(v[0], v[1], v[2]));
    }
    return 0;
}
