// Thin RAII wrappers of the SQLite C API: a connection, a prepared statement with bound
// parameters, and a transaction that rolls back unless committed. Every SQLite error becomes a
// DatabaseError naming the call, the SQLite message and the database file.
#pragma once

#include <sqlite3.h>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace highlift::componentdb::sqlite {

/// An SQLite failure (I/O, a constraint, a busy database). Carries the SQLite result code.
class Error : public std::runtime_error {
 public:
  Error(const std::string& message, int code) : std::runtime_error(message), code_(code) {}
  int code() const { return code_; }

 private:
  int code_;
};

class Statement;

/// An open database connection. Foreign keys on, a busy timeout, extended result codes.
class Connection {
 public:
  enum class Mode { kReadWriteCreate, kReadWrite, kReadOnly };
  Connection(const std::filesystem::path& file, Mode mode);
  ~Connection();
  Connection(const Connection&) = delete;
  Connection& operator=(const Connection&) = delete;

  sqlite3* handle() const { return db_; }
  const std::string& file() const { return file_; }

  /// Prepares and runs every statement of `sql` (no parameters; for schema text and PRAGMAs).
  void Execute(std::string_view sql);
  /// The first column of the first row of `sql` as an integer (e.g. PRAGMA user_version).
  std::int64_t QueryInteger(std::string_view sql);
  /// Throws Error for result code `rc` unless it is SQLITE_OK/ROW/DONE.
  void Check(int rc, std::string_view what) const;
  std::int64_t LastInsertRowId() const { return sqlite3_last_insert_rowid(db_); }

 private:
  sqlite3* db_ = nullptr;
  std::string file_;
};

/// A prepared statement. Bind parameters by 1-based index, then Step() until it returns false.
class Statement {
 public:
  Statement(Connection& connection, std::string_view sql);
  ~Statement();
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;

  Statement& Bind(int index, std::string_view text);
  Statement& Bind(int index, double value);
  Statement& Bind(int index, std::int64_t value);
  Statement& Bind(int index, std::optional<double> value);  ///< nullopt binds NULL
  Statement& BindNull(int index);

  /// Runs one step: true when a row is available, false when done.
  bool Step();
  /// Runs a statement that returns no rows.
  void Run();
  /// Resets the statement and clears its bindings, for another run.
  void Reset();

  bool IsNull(int column) const;
  std::string Text(int column) const;
  double Real(int column) const;
  std::int64_t Integer(int column) const;
  std::optional<double> OptionalReal(int column) const;

 private:
  Connection& connection_;
  sqlite3_stmt* statement_ = nullptr;
  std::string sql_;
};

/// BEGIN IMMEDIATE ... COMMIT; rolls back in the destructor unless Commit() was called.
class Transaction {
 public:
  explicit Transaction(Connection& connection);
  ~Transaction();
  Transaction(const Transaction&) = delete;
  Transaction& operator=(const Transaction&) = delete;
  void Commit();

 private:
  Connection& connection_;
  bool done_ = false;
};

/// One snapshot for a read made of several statements (a part's row, then its parameters): BEGIN
/// (deferred) ... COMMIT around them, so an import committed meanwhile (`db import --replace`
/// deletes and re-inserts parts) is seen wholly or not at all, never half. Inside a transaction
/// already it does nothing.
class ReadSnapshot {
 public:
  explicit ReadSnapshot(Connection& connection);
  ~ReadSnapshot();
  ReadSnapshot(const ReadSnapshot&) = delete;
  ReadSnapshot& operator=(const ReadSnapshot&) = delete;

 private:
  Connection& connection_;
  bool began_ = false;
};

}  // namespace highlift::componentdb::sqlite
