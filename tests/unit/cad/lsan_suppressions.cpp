// LeakSanitizer (debug preset) reports allocations that OpenCASCADE's data-exchange toolkits
// make once per process and never free (static editors, unit tables). They are not leaks of
// this project: suppress reports whose stack runs through OpenCASCADE libraries. The hook is
// only consulted when the test runs under LeakSanitizer.

extern "C" const char* __lsan_default_suppressions();

extern "C" const char* __lsan_default_suppressions() {
    return "leak:libTKernel.so\n"
           "leak:libTKXSBase.so\n"
           "leak:libTKSTEP.so\n"
           "leak:libTKSTEPBase.so\n"
           "leak:libTKSTEPAttr.so\n"
           "leak:libTKIGES.so\n";
}
