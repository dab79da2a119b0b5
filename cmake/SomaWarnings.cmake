add_library(soma_warnings INTERFACE)
target_compile_options(soma_warnings INTERFACE -Wall -Wextra -Wno-psabi)
