#include "highlift/componentdb/sqlite.h"

#include <limits>

#include "highlift/core/error.h"
#include "highlift/core/output_file.h"

namespace highlift::componentdb::sqlite {
namespace {

/// What an SQLite result code means for the user of a database file, as a sentence with the
/// remedy. SQLite's own texts ("database is locked", "file is not a database") are left out: the
/// result code closes the message for a bug report.
std::string Sentence(sqlite3* db, int rc) {
  switch (rc & 0xff) {
    case SQLITE_BUSY:
    case SQLITE_LOCKED:
      return "another process holds the file locked (for more than 5 s); try again when it has finished";
    case SQLITE_READONLY:
      return "the file or its folder is read-only; check the permissions, or give a writable file";
    case SQLITE_CANTOPEN:
      return "the file cannot be opened; check that the path and its folder exist and are readable (and writable to "
             "create or change it)";
    case SQLITE_NOTADB:
      return "the file is not an SQLite database (nor a highlift database); give the right file";
    case SQLITE_CORRUPT:
      return "the file is damaged; restore it from a copy (or remove a component database to re-create the shipped "
             "one)";
    case SQLITE_FULL:
      return "the disk is full; free some disk space";
    case SQLITE_IOERR:
      return "reading or writing the file failed (an input/output error of the disk or file system)";
    case SQLITE_PERM:
    case SQLITE_AUTH:
      return "permission denied; check the permissions of the file and its folder";
    case SQLITE_NOMEM:
      return "out of memory";
    case SQLITE_CONSTRAINT: {
      // "UNIQUE constraint failed: parts.designation" -> which column repeats
      const std::string text = db ? sqlite3_errmsg(db) : "";
      const auto colon = text.find(": ");
      if ((rc == SQLITE_CONSTRAINT_UNIQUE || rc == SQLITE_CONSTRAINT_PRIMARYKEY) && colon != std::string::npos)
        return "a row repeats a value that must be unique (" + text.substr(colon + 2) + ")";
      return "a row breaks a rule of the file's tables";
    }
    case SQLITE_ERROR: {
      // "no such table: runs", "table runs has no column named x": a file of another program or
      // version, or one edited by hand. Said as such, with SQLite's words only as a detail.
      const std::string text = db ? CleanText(sqlite3_errmsg(db), 200) : "";
      if (text.find("no such table") != std::string::npos || text.find("no such column") != std::string::npos ||
          text.find("has no column") != std::string::npos)
        return "the file lacks a table or column this highlift reads (" + text +
               "): it was written by another program or version of highlift, or edited; give a file this highlift "
               "wrote";
      return "the file's contents do not fit what this highlift reads (" + text + ")";
    }
    default:
      // Not a sentence of ours: SQLite's own words, marked as such (issue 27 item 19).
      return "the SQLite library failed (" + CleanText(db ? sqlite3_errmsg(db) : sqlite3_errstr(rc), 200) + ")";
  }
}

std::string Message(sqlite3* db, int rc, std::string_view what, const std::string& file) {
  return "'" + file + "': " + Sentence(db, rc) + " (SQLite result code " + std::to_string(rc) + " in " +
         std::string(what.substr(0, 40)) + ")";
}

}  // namespace

Connection::Connection(const std::filesystem::path& file, Mode mode) : file_(file.string()) {
  int flags = SQLITE_OPEN_NOMUTEX;
  switch (mode) {
    case Mode::kReadWriteCreate: flags |= SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE; break;
    case Mode::kReadWrite: flags |= SQLITE_OPEN_READWRITE; break;
    case Mode::kReadOnly: flags |= SQLITE_OPEN_READONLY; break;
  }
  const int rc = sqlite3_open_v2(file_.c_str(), &db_, flags, nullptr);
  if (rc != SQLITE_OK) {
    const std::string m = Message(db_, rc, "open", file_);
    sqlite3_close(db_);
    db_ = nullptr;
    throw Error(m, rc);
  }
  // Every database a command opens is one of its inputs: no output file may be written over it
  // (a campaign's result file given to `report --campaign` and as `--out`, a component database).
  RegisterInputFile(file);
  sqlite3_extended_result_codes(db_, 1);
  sqlite3_busy_timeout(db_, 5000);
  Execute("PRAGMA foreign_keys = ON");
}

Connection::~Connection() {
  if (db_) sqlite3_close_v2(db_);
}

void Connection::Check(int rc, std::string_view what) const {
  if (rc == SQLITE_OK || rc == SQLITE_ROW || rc == SQLITE_DONE) return;
  throw Error(Message(db_, rc, what, file_), rc);
}

void Connection::Execute(std::string_view sql) {
  const char* tail = sql.data();
  const char* end = sql.data() + sql.size();
  while (tail < end) {
    sqlite3_stmt* statement = nullptr;
    const char* next = nullptr;
    const int rc = sqlite3_prepare_v2(db_, tail, static_cast<int>(end - tail), &statement, &next);
    if (rc != SQLITE_OK) {
      sqlite3_finalize(statement);
      Check(rc, std::string("prepare of \"") + std::string(tail, std::min<std::size_t>(end - tail, 60)) + "\"");
    }
    if (statement == nullptr) break;  // only whitespace or comments left
    int step;
    while ((step = sqlite3_step(statement)) == SQLITE_ROW) {
    }
    const std::string text = sqlite3_sql(statement) ? sqlite3_sql(statement) : "";
    sqlite3_finalize(statement);
    Check(step, "\"" + text.substr(0, 60) + "\"");
    tail = next;
  }
}

std::int64_t Connection::QueryInteger(std::string_view sql) {
  Statement s(*this, sql);
  if (!s.Step()) throw Error("SQLite query returned no row: " + std::string(sql), SQLITE_ERROR);
  return s.Integer(0);
}

Statement::Statement(Connection& connection, std::string_view sql)
    : connection_(connection), sql_(sql) {
  const int rc = sqlite3_prepare_v2(connection_.handle(), sql.data(), static_cast<int>(sql.size()),
                                    &statement_, nullptr);
  if (rc != SQLITE_OK) {
    sqlite3_finalize(statement_);
    statement_ = nullptr;
    connection_.Check(rc, "prepare of \"" + sql_ + "\"");
  }
}

Statement::~Statement() { sqlite3_finalize(statement_); }

Statement& Statement::Bind(int index, std::string_view text) {
  connection_.Check(sqlite3_bind_text(statement_, index, text.data(), static_cast<int>(text.size()),
                                      SQLITE_TRANSIENT),
                    "bind");
  return *this;
}
Statement& Statement::Bind(int index, double value) {
  connection_.Check(sqlite3_bind_double(statement_, index, value), "bind");
  return *this;
}
Statement& Statement::Bind(int index, std::int64_t value) {
  connection_.Check(sqlite3_bind_int64(statement_, index, value), "bind");
  return *this;
}
Statement& Statement::Bind(int index, std::optional<double> value) {
  return value ? Bind(index, *value) : BindNull(index);
}
Statement& Statement::BindNull(int index) {
  connection_.Check(sqlite3_bind_null(statement_, index), "bind");
  return *this;
}

bool Statement::Step() {
  const int rc = sqlite3_step(statement_);
  if (rc == SQLITE_ROW) return true;
  if (rc == SQLITE_DONE) return false;
  connection_.Check(rc, "\"" + sql_.substr(0, 80) + "\"");
  return false;
}

void Statement::Run() {
  while (Step()) {
  }
}

void Statement::Reset() {
  sqlite3_reset(statement_);
  sqlite3_clear_bindings(statement_);
}

bool Statement::IsNull(int column) const { return sqlite3_column_type(statement_, column) == SQLITE_NULL; }

std::string Statement::Text(int column) const {
  const auto* p = reinterpret_cast<const char*>(sqlite3_column_text(statement_, column));
  if (!p) return {};
  return std::string(p, static_cast<std::size_t>(sqlite3_column_bytes(statement_, column)));
}

double Statement::Real(int column) const {
  // SQLite stores +-infinity as REAL; NULL reads back as 0, so callers check IsNull first.
  return sqlite3_column_double(statement_, column);
}

std::int64_t Statement::Integer(int column) const { return sqlite3_column_int64(statement_, column); }

std::optional<double> Statement::OptionalReal(int column) const {
  if (IsNull(column)) return std::nullopt;
  return Real(column);
}

Transaction::Transaction(Connection& connection) : connection_(connection) {
  connection_.Execute("BEGIN IMMEDIATE");
}

Transaction::~Transaction() {
  if (!done_) sqlite3_exec(connection_.handle(), "ROLLBACK", nullptr, nullptr, nullptr);
}

void Transaction::Commit() {
  connection_.Execute("COMMIT");
  done_ = true;
}

ReadSnapshot::ReadSnapshot(Connection& connection) : connection_(connection) {
  if (sqlite3_get_autocommit(connection_.handle()) == 0) return;  // a transaction is open already
  connection_.Execute("BEGIN");
  began_ = true;
}

ReadSnapshot::~ReadSnapshot() {
  // Only reads happened: COMMIT ends the read transaction (a failure leaves nothing to undo).
  if (began_ && sqlite3_exec(connection_.handle(), "COMMIT", nullptr, nullptr, nullptr) != SQLITE_OK)
    sqlite3_exec(connection_.handle(), "ROLLBACK", nullptr, nullptr, nullptr);
}

}  // namespace highlift::componentdb::sqlite
