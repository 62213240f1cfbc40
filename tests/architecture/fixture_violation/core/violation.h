#pragma once
// Deliberately violates the dependency rule: the architecture check must reject this tree.
#include <QString>
