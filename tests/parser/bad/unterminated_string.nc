msg "abc
