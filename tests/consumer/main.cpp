// SPDX-License-Identifier: MIT
// Loads a model through the installed library and prints its patch count.
#include <seamless/model/model.h>

#include <iostream>

int main(int argc, char** argv) {
    if (argc != 2) return 2;
    const seamless::Model m = seamless::load_model(argv[1]);
    std::cout << seamless::bezier_patches(m).size() << "\n";
    return 0;
}
