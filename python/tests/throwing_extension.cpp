// An extension whose registration throws something that is not a
// std::exception: akvf.load_extension must still raise an akvf error naming
// the file.
extern "C" void akvf_register_extension() { throw 42; }
