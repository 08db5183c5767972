// Schema migrations of the component database.
#pragma once

#include "highlift/componentdb/sqlite.h"

namespace highlift::componentdb {

/// Brings the schema from its PRAGMA user_version up to `target`, each migration in its own
/// transaction together with the new user_version.
void Migrate(sqlite::Connection& connection, int target);

}  // namespace highlift::componentdb
