-- Filetype detection for ABB RAPID: extensions in any letter case, and for
-- the extensions that other languages use too (.mod, .sys, .prg) the content.
local M = {}

--- True when the buffer looks like a RAPID module: its first non-blank line
--- starts a `%%%` header or is `MODULE name`, alone or followed by the
--- attribute list or a comment (Modula-2's `MODULE name;` is not RAPID).
---@param bufnr integer
---@return boolean
function M.is_rapid(bufnr)
  local ok, lines = pcall(vim.api.nvim_buf_get_lines, bufnr, 0, 50, false)
  if not ok then
    return false
  end
  for _, line in ipairs(lines) do
    line = line:gsub('^\239\187\191', '') -- a UTF-8 byte-order mark
    if line:match('^%s*$') == nil then
      if line:match('^%s*%%%%%%') then
        return true
      end
      local rest = line:lower():match('^%s*module%s+%a[%w_]*%s*(.*)$')
      return rest ~= nil and (rest == '' or rest:sub(1, 1) == '(' or rest:sub(1, 1) == '!')
    end
  end
  return false
end

-- Neovim's own detector for an extension (it may know other languages).
local function builtin(ext, path, bufnr)
  local ok, detect = pcall(require, 'vim.filetype.detect')
  if ok and type(detect[ext]) == 'function' then
    local ok2, ft, on_detect = pcall(detect[ext], path, bufnr)
    if ok2 then
      return ft, on_detect
    end
  end
  return nil
end

local function by_content(ext)
  return function(path, bufnr)
    if M.is_rapid(bufnr) then
      return 'rapid'
    end
    return builtin(ext, path, bufnr)
  end
end

function M.register()
  local extension = {}
  for _, ext in ipairs({ 'mod', 'sys', 'prg' }) do
    extension[ext] = by_content(ext)
    extension[ext:upper()] = by_content(ext)
  end
  for _, ext in ipairs({ 'modx', 'sysx' }) do
    extension[ext] = 'rapid'
    extension[ext:upper()] = 'rapid'
  end
  vim.filetype.add({
    extension = extension,
    pattern = {
      -- mixed case (Main.Mod); lower priority than the extension table
      ['.*%.[mM][oO][dD][xX]'] = { 'rapid', { priority = -1 } },
      ['.*%.[sS][yY][sS][xX]'] = { 'rapid', { priority = -1 } },
      ['.*%.[mM][oO][dD]'] = { by_content('mod'), { priority = -1 } },
      ['.*%.[sS][yY][sS]'] = { by_content('sys'), { priority = -1 } },
      ['.*%.[pP][rR][gG]'] = { by_content('prg'), { priority = -1 } },
    },
  })
end

return M
