-- :RapidDiff: the Markdown report of `rapid diff` (what really changed
-- between two backups, task folders, modules or git revisions) in a
-- scratch buffer.
--
--   :RapidDiff OLD            OLD (a backup, folder or module) against the current project
--   :RapidDiff OLD NEW        two backups, folders or modules
--   :RapidDiff HEAD~1 HEAD -- cell/    any arguments of `rapid diff`, as given
local M = {}

--- The `rapid` binary: the first word of the server command.
local function binary()
  local cmd = require('rapid').config.cmd
  return type(cmd) == 'table' and cmd[1] or 'rapid'
end

--- The arguments of `rapid diff` for the command's: one path alone is
--- compared with the current buffer's project (or the working folder).
---@param args string[]
---@return string[]
function M.arguments(args)
  if #args == 1 and vim.uv.fs_stat(vim.fn.expand(args[1])) then
    local buf = vim.api.nvim_get_current_buf()
    local name = vim.api.nvim_buf_get_name(buf)
    local root = name ~= '' and require('rapid').find_root(name) or nil
    return { vim.fn.expand(args[1]), root or vim.fn.getcwd() }
  end
  local out = {}
  for _, a in ipairs(args) do
    table.insert(out, vim.fn.expand(a))
  end
  return out
end

--- Runs `rapid diff ARGS --format markdown` and shows the report in a new
--- tab (a Markdown scratch buffer); errors go to a notification.
---@param args string[]
---@return integer|nil the report's buffer
function M.open(args)
  local argv = { binary(), 'diff', '--format', 'markdown' }
  vim.list_extend(argv, M.arguments(args))
  local ok, result = pcall(function()
    return vim.system(argv, { text = true }):wait()
  end)
  if not ok then
    vim.notify('rapid diff: ' .. tostring(result), vim.log.levels.ERROR)
    return nil
  end
  if result.code ~= 0 then
    vim.notify('rapid diff: ' .. vim.trim(result.stderr or ''), vim.log.levels.ERROR)
    return nil
  end
  vim.cmd('tabnew')
  local buf = vim.api.nvim_get_current_buf()
  vim.bo[buf].buftype = 'nofile'
  vim.bo[buf].bufhidden = 'wipe'
  vim.bo[buf].swapfile = false
  vim.api.nvim_buf_set_lines(buf, 0, -1, false, vim.split(result.stdout, '\n', { trimempty = true }))
  vim.bo[buf].modifiable = false
  vim.bo[buf].filetype = 'markdown'
  pcall(vim.api.nvim_buf_set_name, buf, 'rapid diff ' .. table.concat(args, ' '))
  return buf
end

return M
