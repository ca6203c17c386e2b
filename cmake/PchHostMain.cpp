// The source of the program that carries parksim's shared precompiled header for test programs
// (cmake/TargetDefaults.cmake): a program, so that the header is compiled as programs are
// (-fPIE). It is linked but never run.
int main() { return 0; }
