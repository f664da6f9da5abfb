#include "app.h"

int main(int argc, char** argv) { return vkrt::runVkrt(argc, argv); }
